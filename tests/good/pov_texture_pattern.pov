// POV-Ray's patterned textures (doc/language.md "Layered textures"): a block pattern's list of
// textures, a texture_map (entries are texture bodies, a declared texture among them), average,
// transforms of the whole, normals that follow the pattern, and finishes that differ (each entry
// lit with its own).
#declare Dark = texture { pigment { rgb 0.1 } finish { diffuse 0.8 specular 0.6 } }
#declare Light = texture { pigment { rgb <0.9, 0.8, 0.7> } finish { diffuse 0.8 specular 0.6 } normal { bumps 0.3 } }
plane { y, 0 texture { checker texture { Dark } texture { Light scale 0.5 } scale 4 translate <0.7, 0, 1> } }
sphere { 0, 1 texture { gradient y texture_map { [0 Dark] [0.5 pigment { rgb 1 } finish { phong 1 }] [1 Light] } } }
sphere { 0, 1 texture { average texture_map { [1 Dark] [3 Light] } } }
#declare Tiles = texture { hexagon texture { Dark } texture { Light } texture { pigment { agate } } rotate x * 90 }
box { -1, 1 texture { Tiles scale 2 } }
sphere { 0, 1 texture { uv_mapping pigment { checker rgb 1 rgb 0 scale 0.1 } normal { bumps 0.2 } } } // the whole texture at <u, v, 0>
