// a zero direction has no ray
#declare S = sphere { 0, 1 }
#declare P = trace(S, <0, 0, -5>, <0, 0, 0>);
