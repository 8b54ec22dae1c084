// A mesh file that does not exist.
mesh {
  file "no_such_mesh.obj"
}
