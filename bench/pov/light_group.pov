// light_group.pov (bench/pov_side.sh): POV-Ray's light_group. A red light lights the left sphere
// alone (its group, global_lights off: the white light does not light it); the white light lights
// the plane and the right sphere, which the red light does not reach (no red on the plane, no
// shadow of the left sphere in red). A middle sphere in a group with global_lights on: lit by both.
global_settings { assumed_gamma 1 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 45 }
light_source { <4, 8, -6> color rgb 0.9 }
plane { y, 0 pigment { color rgb 0.7 } finish { ambient 0 } }
light_group {
  light_source { <-6, 4, -3> color rgb <1.2, 0.2, 0.1> }
  sphere { <-2.2, 1, 0>, 1 pigment { color rgb 0.9 } finish { ambient 0 } }
}
light_group {
  light_source { <0, 4, -6> color rgb <0.1, 0.3, 1> }
  sphere { <0, 1, 0>, 1 pigment { color rgb 0.9 } finish { ambient 0 } }
  global_lights on
}
sphere { <2.2, 1, 0>, 1 pigment { color rgb 0.9 } finish { ambient 0 } }
