#declare F = function { G(x, y, z) * 2 }
