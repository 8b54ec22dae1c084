#declare F = function(a, b) { a*b }
#declare X = F(1, 2, 3);
