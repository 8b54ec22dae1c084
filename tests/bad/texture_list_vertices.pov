// POV-Ray interpolates per-vertex textures across a triangle: not supported
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } face_indices { 1, <0, 1, 2>, 0, 1, 1 } }
