// A file (found by fuzz_mesh) beginning "ply1" and NUL bytes: not PLY to the structural check,
// PLY to Assimp, whose reader crashed on it.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "first_line.ply" }
