sphere { 0, 1 pigment { gradient <0, 0, 0> } }
