#declare S = spline { 0, <1, 2> 1, <3, 4> }
#declare F = function { S(x).x }
