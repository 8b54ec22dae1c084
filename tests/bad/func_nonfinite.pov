#declare F = function { 1/x }
#declare X = F(0, 1, 2);
