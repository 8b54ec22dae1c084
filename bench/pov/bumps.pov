// bumps at three pattern scales and on a scaled object: POV-Ray keeps the bumps' angle whatever
// the scale (Warp_Normal makes the normal unit in the pattern's space). bench/pov_side.sh's scene
// for the normals' amplitude.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.6 } normal { bumps 0.5 scale 0.3 } }
sphere { <-2.2, 1, 0>, 1 pigment { rgb <0.8, 0.6, 0.4> } normal { bumps 0.8 scale 0.1 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.4, 0.6, 0.8> } normal { bumps 0.8 scale 0.5 } }
sphere { <0, 0, 0>, 0.1 pigment { rgb <0.6, 0.8, 0.4> } normal { bumps 0.8 scale 0.03 } scale 10 translate <2.2, 1, 0> }
