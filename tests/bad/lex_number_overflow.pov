#declare A = 1e999;
