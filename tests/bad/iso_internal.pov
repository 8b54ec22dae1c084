#declare f_pillow = function { internal(48) }
isosurface { function { f_pillow(x, y, z, 1) - 0.5 } contained_by { sphere { 0, 1 } } }
