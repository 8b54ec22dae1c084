// A function pattern calling a pattern function circe cannot evaluate is refused where it is written.
#declare F = function { pattern { aoi } }
sphere { 0, 1 pigment { function { F(x, y, z) } } }
