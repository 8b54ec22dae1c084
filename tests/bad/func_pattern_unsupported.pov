// A pattern circe lacks in a pattern function (functions.inc's f_mandel) is declared without
// complaint and refused, by its name, where the function is called.
#declare M = function { pattern { mandel 25 } }
#declare X = M(1, 2, 3);
