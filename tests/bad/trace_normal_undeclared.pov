// the normal goes into a declared name, as POV-Ray asks
#declare S = sphere { 0, 1 }
#declare P = trace(S, <0, 0, -5>, z, Norm);
