// pat_quilted.pov (bench/pov_cover.sh): quilted
#version 3.7;
#declare P = pigment { quilted control0 0 control1 1 scale 0.5 color_map { [0 rgb 0.1] [1 rgb <1, 0.9, 0.6>] } }
#include "pat_stage.inc"
