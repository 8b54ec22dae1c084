#declare A = 1
sphere { 0, A }
