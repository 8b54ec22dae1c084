// crackle's metric is the exponent of its distance: > 0.
sphere { 0, 1 pigment { crackle metric 0 } }
