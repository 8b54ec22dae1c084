// looks_like_ll3.pov (light19b): the red light in a difference scaled 2 in the looks_like: the pool at <4, 4, 2>
global_settings { assumed_gamma 1 }
camera { location <0, 14, -0.001> look_at 0 angle 60 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 4, 0> color rgb <0, 0, 0.6>
  looks_like { difference {
    sphere { 0, 0.3 pigment { rgb 1 } finish { ambient 1 } }
    sphere { <0,0.3,0>, 0.2 }
    light_source { <3, 0, 0> color rgb <1, 0, 0> }
    scale 2
  } }
  translate <-2, 0, 2>
}
