// pat_onion.pov (bench/pov_cover.sh): onion
#version 3.7;
#declare P = pigment { onion scale 0.6 color_map { [0 rgb 0.1] [1 rgb <0.9, 0.5, 0.1>] } }
#include "pat_stage.inc"
