#declare f_pattern = function { internal(77) }
#declare X = f_pattern(1, 2, 3);
