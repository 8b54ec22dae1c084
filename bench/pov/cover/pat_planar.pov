// pat_planar.pov (bench/pov_cover.sh): planar
#version 3.7;
#declare P = pigment { planar scale 1.1 color_map { [0 rgb 0] [1 rgb <1, 1, 0.5>] } }
#include "pat_stage.inc"
