// nrm_crackle.pov (bench/pov_cover.sh): crackle as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { crackle 0.8 scale 0.4 }
#include "pat_stage.inc"
