// trace of a name never declared
#declare P = trace(Obj, <0, 0, 0>, x);
