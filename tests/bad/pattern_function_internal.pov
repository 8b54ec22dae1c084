// A function pattern calling an internal function circe lacks is refused where it is written.
#declare f_odd = function { internal(43) }
sphere { 0, 1 pigment { function { f_odd(x, y, z, 1) } } }
