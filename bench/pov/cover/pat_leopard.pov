// pat_leopard.pov (bench/pov_cover.sh): leopard
#version 3.7;
#declare P = pigment { leopard scale 0.12 color_map { [0 rgb 0.9] [1 rgb <0.3, 0.15, 0>] } }
#include "pat_stage.inc"
