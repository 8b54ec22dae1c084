// POV-Ray's projected_through: the light reaches a point only through the object, which is not
// placed in the scene; the light's later transforms move it (translate y*2 here), a declared
// light's copy carries its own (the copy's translate moves only its objects).
#declare Ring = torus { 1, 0.1 rotate 90*x }
#declare L = light_source { <0, 4, -10> color 2 projected_through { object { Ring } scale 0.5 } translate y*2 }
light_source { L }
light_source { L translate x }
light_source { <0, 9, 0> color 1 parallel point_at 0 projected_through { box { -1, 1 } } }
