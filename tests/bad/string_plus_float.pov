#declare S = "a" + 1;
