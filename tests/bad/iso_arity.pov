isosurface { function (a) { a * 2 } }
