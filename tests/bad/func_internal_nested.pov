#declare f_pattern = function { internal(77) }
#declare f_pattern2 = function { 2*f_pattern(x, y, z) - 1 }
#declare X = f_pattern2(1, 2, 3);
