// pat_spiral2.pov (bench/pov_cover.sh): spiral2
#version 3.7;
#declare P = pigment { spiral2 3 scale 0.8 color_map { [0 rgb 1] [1 rgb <0, 0.4, 0.8>] } }
#include "pat_stage.inc"
