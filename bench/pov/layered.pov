// layered.pov (bench/pov_side.sh): layered textures, each layer lit with its own finish
// (doc/language.md "Layered textures"): a dull bozo base with ambient under a filtered, glossy
// granite (intee1.pov's two layers); a red base with phong under transmitting white stripes of
// their own brilliance; a matte blue base under a layer that filters it green with a highlight.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
sphere { <-2.2, 1, 0>, 1
  texture { finish { ambient 0.25 } pigment { bozo color_map { [0 rgb <0.9, 0.75, 0.75>] [1 rgb 0.6] } scale 0.4 } }
  texture { finish { specular 0.2 roughness 0.02 phong 0.25 phong_size 75 brilliance 4 }
            pigment { granite color_map { [0 0.9 color rgbf <0.85, 0.6, 0.6, 1> color rgbf <0.85, 0.6, 0.6, 0.5>]
                                          [0.9 1 color rgb <0.18, 0.31, 0.31> color rgb <0.18, 0.31, 0.31>] } scale 2 } } }
sphere { <0, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.15, 0.15> } finish { phong 0.8 phong_size 60 ambient 0.05 } }
  texture { pigment { gradient y color_map { [0 rgbt 1] [0.5 rgbt 1] [0.5 rgb 0.9] [1 rgb 0.9] } scale 0.5 }
            finish { diffuse 0.9 brilliance 2 ambient 0 } } }
sphere { <2.2, 1, 0>, 1
  texture { pigment { rgb <0.2, 0.3, 0.9> } finish { diffuse 0.8 ambient 0.1 } }
  texture { pigment { rgbf <0.3, 1, 0.4, 0.8> } finish { specular 0.6 roughness 0.01 diffuse 0.6 ambient 0 } } }
