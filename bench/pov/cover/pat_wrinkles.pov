// pat_wrinkles.pov (bench/pov_cover.sh): wrinkles
#version 3.7;
#declare P = pigment { wrinkles scale 0.6 }
#include "pat_stage.inc"
