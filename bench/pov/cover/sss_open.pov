// sss_open.pov (bench/pov_cover.sh): POV-Ray's subsurface syntax on open and closed objects
// (doc/language.md "POV-Ray's subsurface", "Brightness"): a marble plane (open: POV-Ray's diffuse
// estimate doubles there), a wax sphere and a wax dome cut by a plane (an intersection: bounded,
// closed), a jade disc (open) standing on the floor; one point light, no highlights.
#version 3.7;
global_settings { assumed_gamma 1 mm_per_unit 20 subsurface { samples 200, 20 } }
camera { location <0, 3.2, -8> look_at <0, 0.9, 0> angle 46 }
light_source { <-5, 9, -7> color rgb 1 }
plane { y, 0
  texture { pigment { rgb <0.83, 0.79, 0.75> * 0.6 } finish { diffuse 0.9 subsurface { translucency <0.4562, 0.3811, 0.3325> } } }
  interior { ior 1.5 } }
sphere { <-2.3, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.5, 0.05> } finish { diffuse 0.8 subsurface { translucency <5, 3, 1> * 0.5 } } }
  interior { ior 1.45 } }
intersection { sphere { 0, 1.2 } plane { -y, 0 } translate <0.1, 0, 0.6>
  texture { pigment { rgb <0.75, 0.7, 0.55> } finish { diffuse 0.8 subsurface { translucency <2, 1.5, 1> } } }
  interior { ior 1.4 } }
disc { <2.3, 1.1, 0.3>, <-0.3, 0, -1>, 1
  texture { pigment { rgb <0.3, 0.65, 0.4> } finish { diffuse 0.8 subsurface { translucency <1, 2, 1.2> } } }
  interior { ior 1.5 } }
