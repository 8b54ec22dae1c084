// POV-Ray copies the light_sources of a declared union, CSG or light_group with each
// object { Name }: each copy's lights are moved by the copy's transforms (after the declared
// object's own), and each light_group in it is a new group per copy (the chain inside copied; a
// group around the copy becomes its parent); a light's looks_like objects and projected_through
// objects move with its copy. A copy in a looks_like places its lights too (POV-Ray's
// Post_Process walks the light's children: light_looks_like.pov); in a clipped_by or bounded_by
// it is an error, as in POV-Ray.
#declare Lamp = union { light_source { <0, 5, 0> color 1 } sphere { 0, 1 } translate y }
object { Lamp translate x * 3 }
object { Lamp rotate z * 90 }
#declare Spot = difference {
  box { -1, 1 }
  sphere { 0, 1.2 }
  light_source { 0 color 1 spotlight point_at <0, -1, 0> }
}
object { Spot translate z * 5 }
#declare Pair = union { object { Lamp translate -x } object { Lamp translate x } }
object { Pair translate z * 2 }
#declare G = light_group {
  light_source { <1, 2, 3> color 0.5 }
  sphere { 0, 1 }
  light_group { light_source { <0, 5, 0> color 1 } box { -1, 1 } global_lights on }
}
object { G translate x }
object { G scale 2 }
light_group { light_source { <0, 9, 0> color 1 } object { G } }
light_source { <0, 20, 0> color 0.5 looks_like { Lamp } }
#declare Bulb = union {
  light_source { <0, 5, 0> color 1 looks_like { sphere { 0, 0.2 } } projected_through { disc { <0, 3, 0>, y, 0.5 } } }
  sphere { 0, 1 }
  translate y
}
object { Bulb translate x * 3 }
object { Bulb rotate z * 90 }
