// A PLY file whose header never ends (Assimp 5 would loop forever on it).
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "no_end_header.ply" }
