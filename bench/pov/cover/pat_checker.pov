// pat_checker.pov (bench/pov_cover.sh): checker
#version 3.7;
#declare P = pigment { checker rgb <1, 0.9, 0.2>, rgb <0.1, 0.2, 0.6> scale 0.5 }
#include "pat_stage.inc"
