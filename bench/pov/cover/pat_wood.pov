// pat_wood.pov (bench/pov_cover.sh): wood
#version 3.7;
#declare P = pigment { wood scale 0.25 rotate x * 60 }
#include "pat_stage.inc"
