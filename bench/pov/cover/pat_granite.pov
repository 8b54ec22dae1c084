// pat_granite.pov (bench/pov_cover.sh): granite
#version 3.7;
#declare P = pigment { granite scale 1.5 }
#include "pat_stage.inc"
