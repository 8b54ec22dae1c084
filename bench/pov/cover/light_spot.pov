// light_spot.pov (bench/pov_cover.sh): a spotlight with radius, falloff and tightness 10 and one with tightness 0, in the dark
#include "light_stage.inc"
light_source { <-2, 8, -3> color rgb 1.5 spotlight point_at <-1.5, 0, 0> radius 12 falloff 25 tightness 10 }
light_source { <3, 7, -2> color rgb <1, 0.8, 0.5> spotlight point_at <2.4, 0, 0> radius 8 falloff 16 tightness 0 }
global_settings { ambient_light 0 }
