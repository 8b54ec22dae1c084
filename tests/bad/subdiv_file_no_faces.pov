// A cage file with vertices but no faces.
subdivision_surface { file "subdiv_file_no_faces.obj" }
