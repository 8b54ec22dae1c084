// mesh2 index vectors need no commas between them (POV-Ray's Parse_Vector: `<a> <b>` is two
// vectors, not a comparison), as balcony's cloth.inc and benchmark write them.
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  face_indices { 2
    <0, 1, 2>
    <0, 2, 3>
  }
}
