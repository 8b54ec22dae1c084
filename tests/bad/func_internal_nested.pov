#declare f_noise3d = function { internal(76) }
#declare f_snoise3d = function { 2*f_noise3d(x, y, z) - 1 }
#declare X = f_snoise3d(1, 2, 3);
