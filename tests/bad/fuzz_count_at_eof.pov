mesh2 {
  vertex_vectors { 3