// inc_skies.pov (bench/pov_cover.sh): skies.inc's S_Cloud2 sky_sphere over a plane, the camera
// looking up
#version 3.7;
global_settings { assumed_gamma 1 }
#include "colors.inc"
#include "skies.inc"
camera { location <0, 1, -6> look_at <0, 4, 0> angle 70 }
light_source { <-5, 8, -7> color rgb 1 }
sky_sphere { S_Cloud2 }
plane { y, 0 pigment { rgb 0.5 } }
