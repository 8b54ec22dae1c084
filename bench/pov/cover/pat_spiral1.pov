// pat_spiral1.pov (bench/pov_cover.sh): spiral1
#version 3.7;
#declare P = pigment { spiral1 3 scale 0.8 color_map { [0 rgb 1] [1 rgb <0.8, 0, 0.3>] } }
#include "pat_stage.inc"
