#declare F = function(a) { a }
#declare X = F("one");
