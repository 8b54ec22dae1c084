#declare V = val("abc");
