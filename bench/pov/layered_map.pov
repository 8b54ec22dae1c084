// layered_map.pov (bench/pov_side.sh): layered textures as entries of patterned textures, each
// entry lit per layer with its own finishes, as POV-Ray's ComputeOneTextureColour lights a
// texture_map's entries (doc/language.md "Layered textures"): a checker of a red base under a
// clear glaze with phong (the glaze's highlight on the red squares only) and a matte yellow; a
// gradient blending a blue base under white stripes with their own specular into a green with
// phong.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Glazed =
  texture { pigment { rgb <0.8, 0.2, 0.15> } finish { diffuse 0.7 ambient 0 } }
  texture { pigment { rgbt <1, 1, 1, 0.85> } finish { phong 0.9 phong_size 40 diffuse 0.3 ambient 0 } }
#declare Striped =
  texture { pigment { rgb <0.2, 0.3, 0.8> } finish { diffuse 0.8 ambient 0.05 } }
  texture { pigment { gradient y color_map { [0 rgbt 1] [0.5 rgbt 1] [0.5 rgb 0.9] [1 rgb 0.9] } scale 0.4 }
            finish { diffuse 0.9 specular 0.5 roughness 0.01 ambient 0 } }
sphere { <-1.2, 1, 0>, 1
  texture { checker texture { Glazed } texture { pigment { rgb <0.9, 0.85, 0.3> } finish { diffuse 0.8 ambient 0 } }
            scale 0.5 } }
sphere { <1.2, 1, 0>, 1
  texture { gradient x texture_map { [0.3 Striped] [0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { diffuse 0.6 phong 0.5 ambient 0 }] }
            scale 2 translate <0.2, 0, 0> } }
