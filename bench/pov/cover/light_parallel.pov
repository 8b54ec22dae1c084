// light_parallel.pov (bench/pov_cover.sh): a parallel light: parallel shadows, the same irradiance everywhere
#include "light_stage.inc"
light_source { <-4, 8, -6> color rgb 1 parallel point_at 0 }
