// A cage file that does not exist.
subdivision_surface { file "no_such_cage.obj" level 2 }
