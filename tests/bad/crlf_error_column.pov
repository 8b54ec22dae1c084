sphere { 0, 1 }
box { 0, "a" }
