// Warps other than turbulence, repeat and black_hole are refused.
sphere { 0, 1 pigment { checker warp { spherical } } }
