// pat_boxed.pov (bench/pov_cover.sh): boxed
#version 3.7;
#declare P = pigment { boxed scale 1.6 rotate <20, 30, 0> translate <0.3, -0.2, 0> color_map { [0 rgb 0] [1 rgb <0.5, 1, 0.5>] } }
#include "pat_stage.inc"
