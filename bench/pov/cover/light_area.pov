// light_area.pov (bench/pov_cover.sh): a rectangular area_light 4 x 4, 6 x 6 samples, jitter adaptive 1: soft shadows
#include "light_stage.inc"
light_source { <-3, 7, -4> color rgb 1 area_light <4, 0, 0>, <0, 0, 4>, 6, 6 adaptive 1 jitter }
