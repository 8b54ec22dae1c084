// nrm_ripples.pov (bench/pov_cover.sh): ripples as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { ripples 0.8 frequency 3 }
#include "pat_stage.inc"
