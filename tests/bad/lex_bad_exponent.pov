#declare A = 1e;
