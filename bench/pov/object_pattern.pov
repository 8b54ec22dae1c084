// object_pattern.pov (bench/pov_side.sh): POV-Ray's object pattern: the floor coloured by a CSG
// solid's inside (a box less a sphere, with a torus), a sphere's pigment by a text's inside (a
// pattern object given inline).
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
#declare Cut = union {
  difference { box { -1, 1 } sphere { <0, 0.3, -1>, 0.8 } rotate 20*y }
  torus { 1.6, 0.2 }
}
plane { y, 0
  pigment { object { Cut color rgb <0.8, 0.75, 0.6> color rgb <0.1, 0.3, 0.8> } scale 1.5 }
}
sphere { <2.2, 1, -1.2>, 1
  pigment { object { text { ttf "timrom.ttf" "C" 2, 0 scale 1.8 translate <1.8, 0.4, -2.5> }
                     color rgb <0.9, 0.2, 0.1> color rgb 1 } }
}
