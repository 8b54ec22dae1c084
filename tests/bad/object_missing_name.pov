object { sphere { 0, 1 } }
