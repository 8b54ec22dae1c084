#declare S = spline { 0, <1, 2, 3, 4, 5, 6> }
