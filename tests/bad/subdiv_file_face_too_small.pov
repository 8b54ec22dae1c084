// A cage file with a face of two vertices.
subdivision_surface { file "subdiv_file_face_too_small.obj" }
