#declare Name = "a";
#declare F = function { x + Name }
