#declare F = function(a) { a < 1 ? 1 : a*F(a - 1) }
