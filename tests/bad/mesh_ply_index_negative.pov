// A PLY face naming vertex -5: read as 4294967291, past the vertices (a crash inside Assimp).
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "index_negative.ply" }
