// POV-Ray's tilings 21 to 27 are not in circe
plane { y, 0 pigment { tiling 21 } }
