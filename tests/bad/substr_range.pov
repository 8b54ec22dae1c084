#declare S = substr("abc", 2, 5);
