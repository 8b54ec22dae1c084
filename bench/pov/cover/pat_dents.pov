// pat_dents.pov (bench/pov_cover.sh): dents
#version 3.7;
#declare P = pigment { dents scale 0.5 color_map { [0 rgb 1] [1 rgb <0.4, 0, 0>] } }
#include "pat_stage.inc"
