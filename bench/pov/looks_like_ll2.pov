// looks_like_ll2.pov (light19b): the looks_like's object is a light itself: both light the floor
global_settings { assumed_gamma 1 }
camera { location <0, 14, -0.001> look_at 0 angle 60 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 4, 0> color rgb <0, 0, 0.6>
  looks_like { light_source { <3, 0, 0> color rgb <1, 0, 0> } }
  translate <-2, 0, 2>
}
