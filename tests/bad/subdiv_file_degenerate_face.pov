// A cage file whose quad has a collapsed edge: its corners 2 and 5 are distinct vertices at one
// position, so welded, the quad uses one vertex twice.
subdivision_surface { file "subdiv_file_degenerate_face.obj" }
