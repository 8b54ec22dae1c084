// pat_image_map_hdr.pov (bench/pov_cover.sh): image_map of a Radiance HDR file (povmap96.hdr:
// povray-includes' povmap.png at 96x60, linearised, written by ImageMagick's RGBE encoder)
#version 3.7;
#declare P = pigment { image_map { hdr "povmap96.hdr" interpolate 2 } translate -0.5 scale 2 }
#include "pat_stage.inc"
