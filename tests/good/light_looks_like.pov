// A light_source written in a light's looks_like object (in a union or other CSG, or as the
// looks_like's object itself) lights the scene, as POV-Ray 3.7's Post_Process finds it among the
// light's children: moved with the object (to the light's position, the looks_like's modifiers,
// the light's later transforms and those around it), listed after its light, and a global light
// even where its light is in a light_group (checked with povray: "Light Sources: 2" and the red
// pools where these positions say). A light in an object pattern's or a projected_through's
// object lights nothing (POV-Ray parses and never uses it): a warning, not counted.
// (povray: "Light Sources: 25", circe the 25 lights of no group below.)
// 1: in a union; the light's translate after looks_like moves both: <1, 4, 2>
light_source { <0, 4, 0> color rgb <0, 0, 0.6>
  looks_like { union {
    sphere { 0, 0.2 }
    light_source { <3, 0, 0> color rgb <1, 0, 0> }
  } }
  translate <-2, 0, 2>
}
// 2: the looks_like's object is the light itself: <1, 4, 2>
light_source { <0, 4, 0> color 0.5 looks_like { light_source { <3, 0, 0> color rgb <0, 1, 0> } } translate <-2, 0, 2> }
// 3: in a difference scaled by its looks_like: 2 * <3, 0, 0> + <0, 4, 0> + <-2, 0, 2> = <4, 4, 2>
light_source { <0, 4, 0> color 0.5
  looks_like { difference {
    sphere { 0, 0.3 }
    sphere { <0, 0.3, 0>, 0.2 }
    light_source { <3, 0, 0> color rgb <0, 0, 1> }
    scale 2
  } }
  translate <-2, 0, 2>
}
// 4: its light in a light_group (group 1), the inner light global (no group): <0, 1, 10>
light_group {
  light_source { <0, 0, 10> color 0.25 looks_like { union { sphere { 0, 0.1 } light_source { y color 0.75 } } } }
  sphere { <0, 0, 10>, 1 }
}
// 5: a declared light copied twice, each with its own inner light: <10, 1, 0> then <0, 1, 10>
#declare L = light_source { 0 color 0.1 looks_like { union { sphere { 0, 0.1 } light_source { y color 0.2 } } } }
light_source { L translate x * 10 }
light_source { L translate z * 10 }
// 6: in a declared union placed twice, rotated: the outer at <0, 5, 0> -> <-5, 0, 0> (rotate z 90)
// then + <0, 0, 3>, the inner at <1, 5, 0> -> <-5, 1, 3>; the second copy scaled 2
#declare Post = union {
  light_source { <0, 5, 0> color 0.3 looks_like { union { sphere { 0, 0.1 } light_source { x color 0.4 } } } }
  cylinder { 0, <0, 4.8, 0>, 0.1 }
}
object { Post rotate z * 90 translate z * 3 }
object { Post scale 2 }
// 7: a declared union holding a light, in a looks_like: its light placed: <0, 6, 0> + <0, 20, 0>
#declare Lamp = union { light_source { <0, 5, 0> color 1 } sphere { 0, 1 } translate y }
light_source { <0, 20, 0> color 0.5 looks_like { Lamp } }
// 8: a declared light as the looks_like's object, bare and as object { L }: <1, 30, 0> twice
#declare Bare = light_source { x color 0.6 }
light_source { <0, 30, 0> color 0.5 looks_like { Bare } }
light_source { <0, 30, 0> color 0.5 looks_like { object { Bare } } }
// 9: object { L } in a union placed: <1, 1, 1>; in an object pattern's: a warning, no light
union { object { Bare translate y } sphere { 0, 1 } translate z }
plane { y, -5 pigment { object { union { object { Bare } sphere { 0, 1 } } color rgb 1 color rgb 0 } } }
// 10: in an object pattern (in a union, and a light alone as the pattern's object: inside
// nothing) and in a projected_through: warnings, no light
plane { y, 0 pigment { object { union { sphere { 0, 2 } light_source { <3, 4, 0> color rgb <1, 0, 0> } } color rgb 1 color rgb <0, 1, 0> } } }
light_source { <0, 10, 0> color 0.5 projected_through { union { disc { <0, 5, 0>, y, 3 } light_source { <3, -6, 0> color rgb <1, 0, 0> } } } }
plane { y, -6 pigment { object { light_source { <0, 5, 0> color 1 } color rgb 1 color rgb 0 } } }
// 11: a light_group in a looks_like of a declared union's light, the union placed twice: each
// copy's group new (2, 3), its light and its sphere in it (povray counts the 2 outer lights)
#declare D = union {
  light_source { <0, 40, 0> color 1 looks_like { light_group { light_source { x color 1 } sphere { 0, 0.1 } } } }
  sphere { <0, 35, 0>, 1 }
}
object { D }
object { D translate z }
