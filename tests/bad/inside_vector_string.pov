// inside_vector takes a vector, as POV-Ray's Parse_Mesh2 does
mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } inside_vector "z" }
