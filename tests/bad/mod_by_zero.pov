#declare A = mod(5, 0);
