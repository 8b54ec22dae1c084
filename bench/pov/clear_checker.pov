// A checker of an opaque colour and Clear (rgbf 1) on a sphere with no interior, over a floor:
// POV-Ray's cut-out (one sees the sphere's inside through the clear squares, its shadow is
// checkered). bench/pov_side.sh's scene for a pattern's transparent entries.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
camera { location <0, 2.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <4, 8, -5> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 1.2, 0>, 1.2
	pigment { checker colour rgb <0.2, 0.7, 0.2> colour Clear scale 0.4 }
	finish { phong 0.5 }
}
background { rgb <0.3, 0.4, 0.6> }
