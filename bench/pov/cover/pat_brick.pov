// pat_brick.pov (bench/pov_cover.sh): brick
#version 3.7;
#declare P = pigment { brick rgb 0.85, rgb <0.6, 0.15, 0.1> scale 0.1 }
#include "pat_stage.inc"
