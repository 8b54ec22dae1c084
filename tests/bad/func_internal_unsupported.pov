#declare f_pillow = function { internal(48) }
#declare X = f_pillow(1, 2, 3, 1);
