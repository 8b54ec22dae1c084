// The loop scheme on a cage file of quads.
subdivision_surface { file "subdiv_file_loop_quads.obj" scheme loop }
