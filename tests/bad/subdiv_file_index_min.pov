// A relative index so far back that negating it overflows (found by fuzzing the cage reader).
subdivision_surface { file "subdiv_file_index_min.obj" }
