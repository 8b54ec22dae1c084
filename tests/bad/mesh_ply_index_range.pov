// A PLY face naming vertex 7 of 3: Assimp's triangulation read past the vertices (a crash).
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "index_range.ply" }
