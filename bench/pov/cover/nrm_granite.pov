// nrm_granite.pov (bench/pov_cover.sh): granite as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { granite 0.5 scale 1.5 }
#include "pat_stage.inc"
