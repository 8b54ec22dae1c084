// POV-Ray's slope pattern (the surface normal's angle to a direction): its simple form, a range,
// an altitude weighted by the vectors' lengths, point_at, in a pigment and in a normal.
sphere { 0, 1 pigment { slope y } }
sphere { 0, 1 pigment { slope { <0, -2, 0>, 0, 0.5 } color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 pigment { slope { -y, 0.1, 0.6 altitude 3*y, -1, 2 } turbulence 0.1 } }
sphere { 0, 1 pigment { slope { point_at <10, 20, 0>, 0.5, 1 } } }
sphere { 0, 1 pigment { rgb 0.5 } normal { slope { x altitude y } 0.4 } }
