#declare F = function(a, b) { a*b }
#declare G = function { F(x) + 1 }
