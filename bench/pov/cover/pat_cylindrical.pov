// pat_cylindrical.pov (bench/pov_cover.sh): cylindrical
#version 3.7;
#declare P = pigment { cylindrical scale 1.2 color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.5>] } }
#include "pat_stage.inc"
