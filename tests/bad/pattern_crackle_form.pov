// crackle's form, metric and offset are not there.
sphere { 0, 1 pigment { crackle form <1, 0, 0> } }
