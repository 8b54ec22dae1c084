#declare F = function { x +
