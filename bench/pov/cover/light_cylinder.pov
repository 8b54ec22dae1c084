// light_cylinder.pov (bench/pov_cover.sh): a cylinder light of radius 1.2, falloff 2, tightness 2, in the dark
#include "light_stage.inc"
light_source { <0, 9, -3> color rgb 1.2 cylinder point_at <0, 0, 0.5> radius 1.2 falloff 2 tightness 2 }
global_settings { ambient_light 0 }
