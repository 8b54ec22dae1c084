// pov_lights.pov: POV-Ray's lights without circe's intensity (no falloff), as POV-Ray renders them:
// two point lights about 13 units away, one faded, a circular oriented area light, a spotlight with
// tightness, a cylinder light and a shadowless light over a plane and five red spheres. The same
// file renders in POV-Ray 3.7 (ambient_light 0: POV-Ray adds no ambient; circe reads it, no finish here is explicit).
// render: -W 64 -H 48 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 }
camera { location <0, 4, -12> look_at <0, 1, 0> angle 50 }
light_source { <-8, 9, -6> color rgb <0.45, 0.45, 0.4> }
light_source { <9, 8, -5> color rgb <0.3, 0.32, 0.4> fade_distance 13 fade_power 2 }
light_source { <0, 6, 1> color rgb 0.35 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 jitter circular orient }
light_source { <4, 7, 3> color rgb <0.7, 0.55, 0.3> spotlight point_at <2, 0, 0> radius 18 falloff 30 tightness 5 }
light_source { <-3, 8, 3> color rgb <0.2, 0.4, 0.2> cylinder point_at <-3, 0, 3> radius 1 falloff 1.6 }
light_source { <0, 3, -10> color rgb 0.08 shadowless }
plane { y, 0 texture { pigment { color rgb 0.7 } finish { diffuse 0.6 } } }
#declare Red = texture { pigment { color rgb <0.8, 0.1, 0.08> } finish { diffuse 0.6 } }
sphere { <-4, 1, 1>, 1 texture { Red } }
sphere { <-2, 1, -1>, 1 texture { Red } }
sphere { <0, 1, 1>, 1 texture { Red } }
sphere { <2, 1, -1>, 1 texture { Red } }
sphere { <4, 1, 1>, 1 texture { Red } }
