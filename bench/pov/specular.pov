// specular.pov (bench/pov_side.sh): POV-Ray's specular highlight at three roughness values.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 6, -6> color rgb 0.5 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { specular 0.8 roughness 0.1 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { specular 0.8 roughness 0.02 } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { specular 1 roughness 0.003 } }
