#declare Nope[1] = 2;
