#declare S = substr("abc", 1);
