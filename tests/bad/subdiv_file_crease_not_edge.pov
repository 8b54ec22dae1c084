// A scene crease on a file cage: vertices 0 and 2 of the file are a diagonal.
subdivision_surface {
  file "subdiv_file_crease_not_edge.obj"
  creases { 2, <0, 1>, 2, <0, 2>, 1.5 }
}
