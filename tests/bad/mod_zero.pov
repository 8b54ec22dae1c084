#declare A = mod(1, 0);
