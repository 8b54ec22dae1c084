// A pigment function's result is a colour: the function pattern takes one component of it.
#declare P = function { pigment { rgb <1, 0.5, 0> } }
sphere { 0, 1 pigment { function { P(x, y, z) } } }
