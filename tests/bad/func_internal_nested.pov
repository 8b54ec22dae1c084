#declare f_pillow = function { internal(48) }
#declare f_pillow2 = function { 2*f_pillow(x, y, z, 1) - 1 }
#declare X = f_pillow2(1, 2, 3);
