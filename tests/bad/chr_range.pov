#declare S = chr(300);
