#declare S = spline { 0, <1, 2> 1, "no" }
