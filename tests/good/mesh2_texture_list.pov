// mesh2's texture_list: faces name their texture by index (one index, or three equal ones);
// faces without one take the object's texture. The mesh is placed as one mesh a texture.
mesh2 {
  vertex_vectors { 5, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0>, <2, 1, 0> }
  texture_list { 2, texture { pigment { rgb <1, 0, 0> } } texture { pigment { checker rgb 1 rgb 0 } } }
  face_indices { 3, <0, 1, 2>, 0, <0, 2, 3>, 1, 1, 1, <1, 4, 2> }
  pigment { rgb <0, 0, 1> }
  translate x
}
#declare I = 1;
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 1, texture { pigment { rgb 0.5 } } } face_indices { 1, <0, 1, 2>, 0 } }
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 2 texture { pigment { rgb 0.5 } } texture { pigment { rgb 1 } } } face_indices { 1, <0, 1, 2> I } }
