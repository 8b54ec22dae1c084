// light_point.pov (bench/pov_cover.sh): a point light 12 units away, no fade: no falloff with distance (POV-Ray's rule)
#include "light_stage.inc"
light_source { <-6, 9, -6> color rgb 1 }
