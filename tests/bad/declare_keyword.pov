#declare sphere = 1;
