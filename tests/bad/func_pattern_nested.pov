#declare F = function { pattern { aoi } }
#declare F2 = function { 2*F(x, y, z) - 1 }
#declare X = F2(1, 2, 3);
