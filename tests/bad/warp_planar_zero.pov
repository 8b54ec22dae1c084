// a mapping warp's orientation must have a direction
sphere { 0, 1 pigment { checker warp { planar <0, 0, 0>, 1 } } }
