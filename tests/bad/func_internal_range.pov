#declare F = function { internal(79) }
