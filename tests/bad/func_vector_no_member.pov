#declare T = function { transform { scale 2 } }
#declare F = function { T(x, y, z) * 2 }
