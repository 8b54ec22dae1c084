// declared_lights.pov (bench/pov_side.sh): lights in declared objects, copied with each copy.
// Lamp, a union of a white light over a post, is placed twice: two pools of light on the plane,
// each around its post. G, a light_group of a red light and a sphere, is placed twice: each
// copy's group is its own, so each sphere is lit by its own red light only, from its left: no red
// on the plane, none on the left sphere's right side (were the copies one group, the right copy's
// light, between the spheres, would light it there), and the white lamps, outside the groups, do
// not light the spheres.
global_settings { assumed_gamma 1 }
camera { location <0, 5, -10> look_at <0, 0.5, 0> angle 50 }
plane { y, 0 pigment { color rgb 0.7 } finish { ambient 0 } }
#declare Lamp = union {
  light_source { <0, 2.2, 0> color rgb <1, 0.9, 0.7> }
  cylinder { 0, <0, 1.5, 0>, 0.1 pigment { color rgb 0.5 } finish { ambient 0 } }
}
object { Lamp translate <-3, 0, 1> }
object { Lamp translate <3, 0, 1> }
#declare G = light_group {
  light_source { <-1.5, 0.6, 0> color rgb <1.2, 0.3, 0.2> }
  sphere { <0, 0.6, 0>, 0.6 pigment { color rgb 0.9 } finish { ambient 0 } }
}
object { G translate <-1.5, 0, -1> }
object { G translate <1.5, 0, -1> }
