#declare S = strupr(3);
