// a warp of no kind POV-Ray has
sphere { 0, 1 pigment { checker warp { conical } } }
