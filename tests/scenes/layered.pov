// layered.pov: POV-Ray's layered textures, each layer lit with its own pigment, finish and normal
// (doc/language.md "Layered textures"): a base with ambient under a filtered, glossy granite
// (intee1.pov's layers); red with phong under transmitting white stripes of their own
// brilliance; a declared layered texture scaled (every layer moves), whose bumpy top layer
// filters the base green; a thin box whose two layers both transmit, showing the floor through
// both tints. The same file renders in POV-Ray 3.7.
// render: -W 64 -H 48 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.75 rgb 0.45 } }
#declare Green = texture { pigment { rgb <0.2, 0.3, 0.9> } finish { diffuse 0.8 ambient 0.1 } }
  texture { pigment { rgbf <0.3, 1, 0.4, 0.8> } normal { bumps 0.6 scale 0.1 }
            finish { specular 0.6 roughness 0.01 diffuse 0.6 ambient 0 } }
sphere { <-2.4, 1, 0>, 1
  texture { finish { ambient 0.25 } pigment { bozo color_map { [0 rgb <0.9, 0.75, 0.75>] [1 rgb 0.6] } scale 0.4 } }
  texture { finish { specular 0.2 roughness 0.02 phong 0.25 phong_size 75 brilliance 4 }
            pigment { granite color_map { [0 0.9 color rgbf <0.85, 0.6, 0.6, 1> color rgbf <0.85, 0.6, 0.6, 0.5>]
                                          [0.9 1 color rgb <0.18, 0.31, 0.31> color rgb <0.18, 0.31, 0.31>] } scale 2 } } }
sphere { <0, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.15, 0.15> } finish { phong 0.8 phong_size 60 ambient 0.05 } }
  texture { pigment { gradient y color_map { [0 rgbt 1] [0.5 rgbt 1] [0.5 rgb 0.9] [1 rgb 0.9] } scale 0.5 }
            finish { diffuse 0.9 brilliance 2 ambient 0 } } }
sphere { <2.4, 1, 0>, 1 texture { Green scale 2 } }
box { <-1, 0.01, -2.4>, <1, 0.05, -1.6>
  texture { pigment { rgbt <1, 0.9, 0.3, 0.6> } finish { ambient 0 } }
  texture { pigment { rgbf <0.4, 0.8, 1, 0.7> } finish { phong 0.5 ambient 0 } } }
