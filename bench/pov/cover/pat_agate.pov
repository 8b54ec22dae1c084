// pat_agate.pov (bench/pov_cover.sh): agate
#version 3.7;
#declare P = pigment { agate scale 0.8 }
#include "pat_stage.inc"
