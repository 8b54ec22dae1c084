// level (uniform) and max_edge (adaptive) are alternatives: giving both is an error at the second.
subdivision_surface {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  faces { 1, <0, 1, 2> }
  level 2
  max_edge 1
}
