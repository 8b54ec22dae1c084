#declare S = -"a";
