// CSG: every operator, nesting, inverse on an object and on a node, planes as half-spaces,
// clipped_by and bounded_by (a hint), and copies of a declared solid (each its own solid).
camera { location <0, 2, -6> look_at 0 }
light_source { <5, 8, -5> color rgb 1 }
difference {
  intersection { sphere { 0, 1 } box { -0.8, 0.8 } }
  cylinder { -2*x, 2*x, 0.3 }
  plane { y, 0.5 inverse }
  pigment { color rgb <1, 0.3, 0.2> }
  translate -2*x
}
sphere { 0, 1
  clipped_by { plane { y, 0 } plane { x, 0.5 } }
  bounded_by { box { -1, 1 } }
}
sphere { 2*x, 1 bounded_by { box { <1, -1, -1>, <3, 1, 1> } } clipped_by { bounded_by } }
#declare W = merge { sphere { 0, 1 } sphere { x, 1 } }
object { W translate 2*y }
object { W inverse translate -2*y }
intersection { union { sphere { 0, 1 } sphere { y, 1 } } box { -1, 1 } inverse }
intersection { sphere { 0, 1 } plane { z, 0 } bounded_by { clipped_by } }
