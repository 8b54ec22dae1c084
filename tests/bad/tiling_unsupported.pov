// POV-Ray's Penrose tilings 25 to 27 are not in circe
plane { y, 0 pigment { tiling 25 } }
