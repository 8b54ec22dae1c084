// A PLY header (found by fuzz_mesh) whose lines carry NUL bytes: the structural check read
// "element vertex 33" and stopped at the NUL; Assimp's reader read on and overflowed its heap.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "header_nul.ply" }
