// subsurface.pov (bench/pov_side.sh): POV-Ray's subsurface syntax (doc/language.md "POV-Ray's
// subsurface"): a wax sphere (subsurface.pov's candle's translucency), a white marble block
// (Jensen et al.'s marble: translucency <0.4562, 0.3811, 0.3325>) and a plain sphere of the wax's
// pigment for comparison, on a plane under one point light behind and beside them. No highlights:
// the pair shows the diffusion alone.
#version 3.7;
global_settings { assumed_gamma 1 mm_per_unit 40 subsurface { } }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 8, 6> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
sphere { <-2.2, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.5, 0.05> } finish { diffuse 0.8 subsurface { translucency <5, 3, 1> * 0.5 } } }
  interior { ior 1.45 } }
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> rotate y * 30
  texture { pigment { rgb <0.83, 0.79, 0.75> } finish { diffuse 0.9 subsurface { translucency <0.4562, 0.3811, 0.3325> * 4 } } }
  interior { ior 1.5 } }
sphere { <2.2, 1, 0>, 1 pigment { rgb <0.8, 0.5, 0.05> } finish { diffuse 0.8 } }
