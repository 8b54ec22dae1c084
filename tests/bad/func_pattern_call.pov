#declare P = function { pattern { agate } }
#declare X = P(1, 2, 3);
