// nrm_dents.pov (bench/pov_cover.sh): dents as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { dents 1.5 scale 0.4 }
#include "pat_stage.inc"
