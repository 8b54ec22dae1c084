// csg.pov: POV-Ray's CSG - a rounded cube bored along three axes (difference of an intersection),
// a sphere cut by a plane (a half-space in an intersection), a merge of three spheres in wax
// (SSS on a CSG solid: circles see its boundary), a sphere clipped_by a plane (open: its inside
// shows) and an inverted cylinder in an intersection, on a checker floor.
// render: -W 80 -H 60 --spp 16 --seed 7
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <4, 8, -6> color rgb 1 }
sky_sphere { pigment { color rgb <0.25, 0.35, 0.5> } intensity 1 }
plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.3 } }
difference {
  intersection { sphere { 0, 1 } box { -0.78, 0.78 } }
  cylinder { -2*x, 2*x, 0.4 }
  cylinder { -2*y, 2*y, 0.4 }
  cylinder { -2*z, 2*z, 0.4 }
  pigment { color rgb <0.9, 0.3, 0.2> }
  rotate 30*y translate <-2, 0, 0.5>
}
intersection {
  sphere { 0, 0.9 }
  plane { <1, 1, -1>, 0.2 }
  pigment { color rgb <0.3, 0.8, 0.3> }
  translate <0, -0.1, -1>
}
merge {
  sphere { <-0.4, 0, 0>, 0.6 }
  sphere { <0.4, 0, 0>, 0.6 }
  sphere { <0, 0.55, 0>, 0.5 }
  material { wax { } }
  translate <2, -0.35, 0.8>
}
intersection {
  sphere { 0, 0.7 clipped_by { plane { -z, 0 } } }
  cylinder { -y, y, 0.3 inverse }
  pigment { color rgb <0.3, 0.4, 1> }
  rotate <0, -30, 0> translate <0.3, 0.7, 2>
}
