// form, metric, offset and solid belong to crackle.
sphere { 0, 1 pigment { bozo form <1, 0, 0> } }
