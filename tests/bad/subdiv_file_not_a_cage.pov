// A PLY cage (read through Assimp) that is not a PLY file.
subdivision_surface { file "subdiv_file_not_a_cage.ply" }
