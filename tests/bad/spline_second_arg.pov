#declare S = spline { 0, <1, 2> 1, <3, 4> }
#declare V = S(0.5, 2);
