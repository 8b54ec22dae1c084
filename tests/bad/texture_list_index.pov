// a texture index past the texture_list
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0, 1, 2>, 1 } }
