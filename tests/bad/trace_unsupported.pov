// Functions that need the scene's geometry are named as unsupported.
#declare P = trace(Obj, <0, 0, 0>, x);
