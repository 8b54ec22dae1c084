// nrm_bump_map.pov (bench/pov_cover.sh): bump_map of povray-includes' povmap.png on a white pigment
#version 3.7;
#declare P = pigment { rgb 0.8 }
#declare N = normal { bump_map { png "povmap.png" interpolate 2 bump_size 3 } translate -0.5 scale 2 }
#include "pat_stage.inc"
