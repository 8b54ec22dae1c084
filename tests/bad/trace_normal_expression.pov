// the normal goes into a name, not an expression
#declare S = sphere { 0, 1 }
#declare N = 0;
#declare P = trace(S, <0, 0, -5>, z, N + 1);
