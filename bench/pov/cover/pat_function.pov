// pat_function.pov (bench/pov_cover.sh): function
#version 3.7;
#declare P = pigment { function { 0.5 + 0.25 * (sin(3 * x) + cos(4 * y + z)) } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.9, 0.4>] } }
#include "pat_stage.inc"
