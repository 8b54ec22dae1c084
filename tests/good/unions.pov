// unions: nested unions flatten with composed transforms; materials fill children without one;
// object { Name } instances share one geometry record.
#declare Red = material { diffuse { color rgb <1, 0, 0> } }
#declare Blue = material { diffuse { color rgb <0, 0, 1> } }
#declare Pair = union {
  sphere { <-1, 0, 0>, 0.5 }
  sphere { <1, 0, 0>, 0.5 material { Blue } }
  translate y
}
union {
  object { Pair }
  union {
    object { Pair rotate <0, 90, 0> }
    scale 2
  }
  material { Red }
  translate <0, 0, 3>
}
object { Pair no_shadow }
