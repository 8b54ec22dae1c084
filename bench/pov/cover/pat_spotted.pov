// pat_spotted.pov (bench/pov_cover.sh): spotted
#version 3.7;
#declare P = pigment { spotted scale 0.4 }
#include "pat_stage.inc"
