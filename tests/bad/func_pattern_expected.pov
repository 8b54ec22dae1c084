// pattern { } holds a pattern, not a colour.
#declare P = function { pattern { rgb 1 } }
