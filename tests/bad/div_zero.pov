#declare A = div(1, 0);
