// subdiv: an inline cage with uvs, creases, corners, scheme, boundary and level; a file cage.
subdivision_surface {
  vertex_vectors { 5, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0>, <0.5, 0.5, 1> }
  faces { 5, <0, 1, 2, 3>, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 0.5> }
  uv_faces { 5, <0, 1, 2, 3>, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  creases { 2, <0, 1>, 2.5, <2, 4>, 1 }
  corners { 1, 3, 4 }
  scheme catmull_clark
  boundary edge_only
  level 3
  translate x
}
subdivision_surface {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  faces { 4, <0, 2, 1>, <0, 1, 3>, <1, 2, 3>, <0, 3, 2> }
  scheme loop
  max_edge 2
}
subdivision_surface { file "cage.obj" material { skin { } } }
