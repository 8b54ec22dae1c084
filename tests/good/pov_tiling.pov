// POV-Ray's tiling pattern: its 27 tilings (squares and hexagons to Penrose's three); 0 and
// numbers past 27 are squares, as POV-Ray's unsigned char and default.
#for (T, 1, 27)
  plane { y, 0 pigment { tiling T color_map { [0 rgb 0] [1 rgb 1] } } }
#end
plane { y, 0 pigment { tiling 0 } }
plane { y, 0 pigment { tiling 300 } }
sphere { 0, 1 pigment { rgb 1 } normal { tiling 2 0.5 } }
plane { y, 0 pigment { tiling 26 } }
plane { y, 0 pigment { tiling 27 } }
