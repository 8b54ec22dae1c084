// An image_map whose file does not exist: check opens every file the scene names.
sphere { 0, 1
  texture { pigment { image_map { png "no_such.png" } } }
}
