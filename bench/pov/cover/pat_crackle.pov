// pat_crackle.pov (bench/pov_cover.sh): crackle
#version 3.7;
#declare P = pigment { crackle scale 0.5 color_map { [0 rgb 0] [0.05 rgb 0] [0.12 rgb 0.9] [1 rgb 0.9] } }
#include "pat_stage.inc"
