subdivision_surface {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  faces { 1, <0, 1, 2> }
  level 12
}
