#declare F = function(a, b, a) { a }
