// A cage file whose face names a UV it does not have.
subdivision_surface { file "subdiv_file_uv_range.obj" }
