// light_falloff_small.pov (bench/pov_cover.sh): a spotlight and a cylinder whose falloff is below
// their radius, beside a spotlight as usual: POV-Ray lights such a spot inside its radius only and
// such a cylinder out to its falloff only, both with a hard edge.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 50 }
light_source { <-1, 5, 0> color rgb 1 spotlight point_at <-2, 0, 0> radius 20 falloff 10 }
light_source { <1, 5, 0> color rgb 1 spotlight point_at <1.5, 0, 1> radius 10 falloff 20 }
light_source { <1.5, 5, -1.5> color rgb 0.7 cylinder point_at <1.5, 0, -1.5> radius 1.2 falloff 0.6 }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 1 ambient 0 } }
