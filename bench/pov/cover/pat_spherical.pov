// pat_spherical.pov (bench/pov_cover.sh): spherical
#version 3.7;
#declare P = pigment { spherical scale 1.5 color_map { [0 rgb 0] [1 rgb <0.5, 0.5, 1>] } }
#include "pat_stage.inc"
