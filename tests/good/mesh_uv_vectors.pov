// A mesh triangle's uv_vectors (POV-Ray's Parse_Mesh): the corners' uvs, one a corner; a triangle
// of the same mesh without them has uv 0 at its corners; a comma between uvs may be left out
// (POV-Ray's Parse_Comma).
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0, 0>, <1, 0>, <0.25, 1> }
  smooth_triangle { <1, 0, 0>, <0, 0, -1>, <1, 1, 0>, <0, 0, -1>, <0, 1, 0>, <0, 0, -1> }
  triangle { <2, 0, 0>, <3, 0, 0>, <2, 1, 0> uv_vectors <0.5, 0.5> <1, 1>, <2, 2> }
  pigment { uv_mapping checker rgb 1 rgb 0 scale 0.25 }
}
