// pat_bozo.pov (bench/pov_cover.sh): bozo
#version 3.7;
#declare P = pigment { bozo scale 0.4 }
#include "pat_stage.inc"
