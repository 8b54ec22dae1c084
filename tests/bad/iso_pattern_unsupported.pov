#declare F = function { pattern { slope y } }
isosurface { function { F(x, y, z) - 0.5 } contained_by { sphere { 0, 1 } } }
