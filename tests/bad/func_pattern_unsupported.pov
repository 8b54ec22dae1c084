// A pattern circe lacks in a pattern function (slope, a normal's pattern of the surface's
// direction) is declared without complaint and refused, by its name, where the function is called.
#declare M = function { pattern { slope y } }
#declare X = M(1, 2, 3);
