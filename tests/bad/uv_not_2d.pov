mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  uv_vectors { 3, <0, 0, 0>, <1, 0>, <0, 1> }
}
