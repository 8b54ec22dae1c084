isosurface { function { x } }
