// looks_like: the object moves to the light's position (as it stands at looks_like) and with the
// light's transforms after it, and is no_shadow (POV-Ray's implied no_shadow); a declared object
// alone, or an object with modifiers.
#declare Bulb = sphere { 0, 0.2 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
light_source { <0, 5, 0> color rgb 1 looks_like { Bulb } translate x * 2 }
light_source { <1, 1, 1> color rgb 1 looks_like { box { -0.1, 0.1 scale 2 pigment { rgb <1, 1, 0> } } } }
