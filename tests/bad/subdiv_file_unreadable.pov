// A cage file whose vertex line is not three numbers.
subdivision_surface {
  file "subdiv_file_unreadable.obj"
}
