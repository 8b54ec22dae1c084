// nrm_wrinkles.pov (bench/pov_cover.sh): wrinkles as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { wrinkles 0.8 scale 0.5 }
#include "pat_stage.inc"
