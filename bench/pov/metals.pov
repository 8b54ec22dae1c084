// metals.inc's textures (brass, copper, chrome, silver: brilliance 2-5, metallic, reflection) on a
// row of spheres over a checker floor, no background: bench/pov_side.sh's scene for the metals.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "metals.inc"
camera { location <0, 3, -8> look_at <0, 1, 0> angle 45 }
light_source { <-5, 10, -10> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 } }
sphere { <-3, 1, 0>, 1 texture { T_Brass_3A } }
sphere { <-1, 1, 0>, 1 texture { T_Copper_3C } }
sphere { <1, 1, 0>, 1 texture { T_Chrome_4D } }
sphere { <3, 1, 0>, 1 texture { T_Silver_2B } }
