// tex_entries.pov: POV-Ray's patterned textures whose entries differ in their finish, each entry
// lit with its own (doc/language.md "Patterned textures"; bench/pov/cover/tex_entry_finish.pov,
// the same scene, beside POV-Ray at r 0.978): a checker of a matte red and a polished, reflecting
// blue; a gradient of a matte white into a glowing green; an average of the two; a brick floor of
// a dull and a shiny texture. The same file renders in POV-Ray 3.7.
// render: -W 64 -H 48 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.4 }
#declare Matte = texture { pigment { rgb <0.8, 0.15, 0.1> } finish { diffuse 0.8 ambient 0 } }
#declare Shiny = texture { pigment { rgb <0.1, 0.2, 0.7> }
                           finish { diffuse 0.3 ambient 0 phong 1 phong_size 60 reflection 0.4 } }
#declare Glow = texture { pigment { rgb <0.2, 0.9, 0.3> } finish { diffuse 0.2 ambient 0.6 } }
#declare White = texture { pigment { rgb 0.9 } finish { diffuse 0.9 ambient 0 } }
plane { y, 0 texture { brick texture { pigment { rgb 0.6 } finish { diffuse 0.7 ambient 0 } }
                           texture { pigment { rgb <0.5, 0.4, 0.3> } finish { diffuse 0.4 specular 0.8 roughness 0.02 ambient 0 } }
                       scale 0.3 } }
sphere { <-2.2, 1, 0>, 1 texture { checker texture { Matte } texture { Shiny } scale 0.5 } }
sphere { <0, 1, 0>, 1 texture { gradient y texture_map { [0.2 White] [0.8 Glow] } scale 2 } }
sphere { <2.2, 1, 0>, 1 texture { average texture_map { [1 Shiny] [1 Matte] } } }
