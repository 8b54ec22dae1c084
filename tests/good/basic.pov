// basic: settings, camera, every light kind, environment, primitives with every transform.
#version 3.7;
global_settings { mm_per_unit 25.4 max_trace_level 8 assumed_gamma 1.0 }
camera {
  perspective
  location <0, 2, -6>
  look_at <0, 0.5, 0>
  sky <0, 1, 0>
  angle 45
  right x * 16 / 9
  up y
  aperture 0.05
  focal_point <0, 0.5, 0>
}
light_source { <5, 10, -5> color rgb <1, 0.9, 0.8> }
light_source { <-5, 10, -5>, colour rgb 1 intensity 3 radius 0.5 }
light_source { <0, 8, 0> color rgb 1 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
light_source { <1, 1, -1> color rgb 0.5 parallel point_at <0, 0, 0> }
background { color rgb <0.1, 0.2, 0.3> }
sphere { <0, 1, 0>, 1 translate <1, 0, 0> }
sphere { 0, 0.5 scale 2 rotate <0, 90, 0> translate -x no_shadow }
box { <-1, 0, -1>, <1, 0.2, 1> scale <2, 1, 3> }
plane { y, 0 }
box { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 6, 7> }
