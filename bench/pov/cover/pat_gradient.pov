// pat_gradient.pov (bench/pov_cover.sh): gradient
#version 3.7;
#declare P = pigment { gradient x color_map { [0 rgb <0, 0, 0.6>] [1 rgb <1, 0.8, 0.3>] } scale 1.3 }
#include "pat_stage.inc"
