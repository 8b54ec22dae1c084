sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1> }
