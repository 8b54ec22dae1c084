// pat_wood_turb.pov (bench/pov_cover.sh): wood_turb
#version 3.7;
#declare P = pigment { wood turbulence 0.1 scale 0.25 rotate x * 60 }
#include "pat_stage.inc"
