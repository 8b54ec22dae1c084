sphere { 0, 1 ] }
