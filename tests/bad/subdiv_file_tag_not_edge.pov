// A crease tag on the diagonal of a quad, which is not an edge.
subdivision_surface { file "subdiv_file_tag_not_edge.obj" }
