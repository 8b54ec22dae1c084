// pat_marble.pov (bench/pov_cover.sh): marble
#version 3.7;
#declare P = pigment { marble scale 0.7 color_map { [0 rgb 0.9] [0.8 rgb <0.6, 0.1, 0.1>] [1 rgb 0] } }
#include "pat_stage.inc"
