// pat_marble_turb.pov (bench/pov_cover.sh): marble_turb
#version 3.7;
#declare P = pigment { marble turbulence 0.8 scale 0.7 }
#include "pat_stage.inc"
