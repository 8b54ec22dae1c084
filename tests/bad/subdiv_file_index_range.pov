// A cage file whose face names a vertex it does not have.
subdivision_surface { file "subdiv_file_index_range.obj" }
