// A function pattern calling an internal function circe lacks is refused where it is written.
#declare f_pat = function { internal(77) }
sphere { 0, 1 pigment { function { f_pat(x, y, z) } } }
