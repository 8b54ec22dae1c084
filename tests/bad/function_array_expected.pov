#declare N = dimensions(3);
