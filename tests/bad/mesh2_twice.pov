mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
}
