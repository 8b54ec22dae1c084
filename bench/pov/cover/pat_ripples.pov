// pat_ripples.pov (bench/pov_cover.sh): ripples
#version 3.7;
#declare P = pigment { ripples frequency 3 color_map { [0 rgb <0, 0.2, 0.5>] [1 rgb <0.7, 0.9, 1>] } }
#include "pat_stage.inc"
