// A black hole's radius must be positive.
sphere { 0, 1 pigment { checker warp { black_hole <0, 0, 0>, 0 } } }
