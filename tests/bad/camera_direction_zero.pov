camera { direction <0, 0, 0> }
