// a bow tie: the outline crosses itself, where POV-Ray's even-odd inside test is undefined
prism { linear_spline 0, 1, 5, <0, 0>, <1, 1>, <1, 0>, <0, 1>, <0, 0> }
