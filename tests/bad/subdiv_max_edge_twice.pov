// max_edge given twice (its own slot: not confused with level).
subdivision_surface {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  faces { 1, <0, 1, 2> }
  max_edge 2
  max_edge 1
}
