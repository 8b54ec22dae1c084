// circe has the fractals of exponent 2 only.
sphere { 0, 1 pigment { mandel 20 exponent 3 } }
