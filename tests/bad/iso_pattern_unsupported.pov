#declare F = function { pattern { aoi } }
isosurface { function { F(x, y, z) - 0.5 } contained_by { sphere { 0, 1 } } }
