#declare A = 0;
sphere { 0, 1 / A }
