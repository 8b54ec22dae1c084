subdivision_surface {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  faces { 1, <0, 1, 2, 3> }
  creases { 2, <0, 1>, 2, <0, 2>, 1.5 }
}
