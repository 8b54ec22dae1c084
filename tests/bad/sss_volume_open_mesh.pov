// A mesh with a border (two triangles of a square) under the volume method.
#declare Wax = material { wax { method volume } }
camera { location <0, 1, -4> look_at <0, 0, 0> }
light_source { <0, 5, -5> color rgb 1 }
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  material { Wax }
}
sphere { <2, 0, 0>, 0.5 material { Wax } }
