// texture_list comes before face_indices (POV-Ray's order)
mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } texture_list { 1, texture { pigment { rgb 1 } } } }
