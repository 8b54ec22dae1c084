// trace needs an object
#declare A = 3;
#declare P = trace(A, <0, 0, -5>, z);
