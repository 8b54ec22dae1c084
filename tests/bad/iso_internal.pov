#declare f_pattern = function { internal(77) }
isosurface { function { f_pattern(x, y, z) - 0.5 } contained_by { sphere { 0, 1 } } }
