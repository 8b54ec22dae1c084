// ambient.pov (bench/pov_side.sh): explicit ambient (scaled by ambient_light) and emission as glow:
// a glowing sphere, a half-lit one, and a lit one without any.
global_settings { assumed_gamma 1 ambient_light rgb <1, 0.9, 0.8> }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 0.6 }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0 } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb <1, 0.8, 0.3> } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.3, 0.5, 1> } finish { ambient 0.4 diffuse 0.6 } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.3, 1, 0.4> } finish { emission 0.5 ambient 0 diffuse 0.5 } }
