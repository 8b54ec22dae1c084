// A boundary rule circe does not have (0: no limit surface at the boundary).
subdivision_surface { file "subdiv_file_boundary_none.obj" }
