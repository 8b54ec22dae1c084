// A pattern circe lacks in a pattern function (aoi, the angle of the ray to the surface, which
// a function has not) is declared without complaint and refused, by its name, where it is called.
#declare M = function { pattern { aoi } }
#declare X = M(1, 2, 3);
