#declare S = "a\q";
