// pat_image_map.pov (bench/pov_cover.sh): image_map
#version 3.7;
#declare P = pigment { image_map { png "povmap.png" interpolate 2 } translate -0.5 scale 2 }
#include "pat_stage.inc"
