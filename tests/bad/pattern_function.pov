// The function pattern takes a float function of x, y and z.
sphere { 0, 1 pigment { function(u, v) { u + v } } }
