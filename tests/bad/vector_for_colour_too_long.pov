#declare V = <1, 2, 3, 4, 5, 6>;
sphere { 0, 1 pigment { color V } }
