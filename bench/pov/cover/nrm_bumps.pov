// nrm_bumps.pov (bench/pov_cover.sh): bumps as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { bumps 0.6 scale 0.3 }
#include "pat_stage.inc"
