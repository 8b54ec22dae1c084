// POV-Ray's P1 Penrose tiling (25) is not in circe
plane { y, 0 pigment { tiling 25 } }
