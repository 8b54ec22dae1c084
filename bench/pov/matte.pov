// matte.pov (bench/pov_side.sh): POV-Ray's diffuse alone: three spheres of diffuse 0.3, 0.6 and 0.9 on
// a plane under one point light.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { diffuse 0.3 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.3, 0.8, 0.3> } finish { diffuse 0.6 } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.3, 0.4, 0.9> } finish { diffuse 0.9 } }
