// A PLY file whose magic is "PLY" (Assimp accepts both cases) and whose header never ends: it was
// not checked as PLY, and Assimp looped forever.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "upper_no_end_header.ply" }
