// light_fade.pov (bench/pov_cover.sh): two point lights with fade_distance / fade_power 1 and 2: 2 / (1 + (d / fade_distance)^fade_power)
#include "light_stage.inc"
light_source { <-5, 6, -3> color rgb <1, 0.9, 0.8> fade_distance 3 fade_power 2 }
light_source { <5, 3, -2> color rgb <0.6, 0.7, 1> fade_distance 4 fade_power 1 }
