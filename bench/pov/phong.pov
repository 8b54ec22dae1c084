// phong.pov (bench/pov_side.sh): POV-Ray's phong highlight at three phong_size values.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 1 phong_size 5 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 1 phong_size 40 } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.7 phong_size 200 } }
