#declare f_noise3d = function { internal(76) }
#declare X = f_noise3d(1, 2, 3);
