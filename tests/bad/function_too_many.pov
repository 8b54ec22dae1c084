#declare S = strlen("abc", "d");
