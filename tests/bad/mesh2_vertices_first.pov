mesh2 {
  face_indices { 1, <0, 1, 2> }
}
