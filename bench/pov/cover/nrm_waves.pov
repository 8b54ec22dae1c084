// nrm_waves.pov (bench/pov_cover.sh): waves as a normal pattern (the shading of its slopes)
#version 3.7;
#declare P = pigment { rgb <0.8, 0.75, 0.7> }
#declare N = normal { waves 0.8 frequency 2 }
#include "pat_stage.inc"
