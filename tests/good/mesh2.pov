// mesh2: vertices, normals, uvs and their index lists; and a mesh loaded from a file.
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  normal_vectors { 1, <0, 0, -1> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  normal_indices { 2, <0, 0, 0>, <0, 0, 0> }
  uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
  rotate <90, 0, 0>
}
mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  normal_vectors { 3, <0, 0, -1>, <0, 0, -1>, <0, 0, -1> }
  face_indices { 1, <0, 1, 2> }
}
mesh { file "head.obj" scale 0.1 }
