// pat_radial.pov (bench/pov_cover.sh): radial
#version 3.7;
#declare P = pigment { radial frequency 6 color_map { [0 rgb 0.05] [0.5 rgb <1, 0.6, 0.2>] [1 rgb 0.05] } }
#include "pat_stage.inc"
