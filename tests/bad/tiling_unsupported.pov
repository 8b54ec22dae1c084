// POV-Ray's tilings 19 to 27 are not in circe
plane { y, 0 pigment { tiling 20 } }
