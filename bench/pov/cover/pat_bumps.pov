// pat_bumps.pov (bench/pov_cover.sh): bumps
#version 3.7;
#declare P = pigment { bumps scale 0.4 color_map { [0 rgb <0, 0, 0.3>] [1 rgb <0.9, 0.9, 1>] } }
#include "pat_stage.inc"
