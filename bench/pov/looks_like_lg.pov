// looks_like_lg.pov (light19b): the outer light in a light_group with the sphere; the red light in its looks_like is global (it lights the floor, not the sphere)
global_settings { assumed_gamma 1 }
camera { location <0, 14, -0.001> look_at 0 angle 60 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_group {
  light_source { <0, 4, 0> color rgb <0, 0, 0.6>
    looks_like { union {
      sphere { 0, 0.2 pigment { rgb 1 } finish { ambient 1 } }
      light_source { <3, 0, 0> color rgb <1, 0, 0> }
    } }
    translate <-2, 0, 2>
  }
  sphere { <0,0,-3>, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
}
