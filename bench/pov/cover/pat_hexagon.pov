// pat_hexagon.pov (bench/pov_cover.sh): hexagon
#version 3.7;
#declare P = pigment { hexagon rgb <0.9, 0.1, 0.1>, rgb <0.1, 0.7, 0.1>, rgb <0.1, 0.1, 0.8> scale 0.35 }
#include "pat_stage.inc"
