// reflection.pov (bench/pov_side.sh): POV-Ray's reflection: the short form, min/max with falloff,
// and a Fresnel reflection with an interior's ior, over a checker of two boxes and a sky colour.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
background { color rgb <0.5, 0.6, 0.8> }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } }
box { <-4, 0, 3>, <-1, 2, 4> pigment { color rgb <0.9, 0.2, 0.1> } }
box { <1, 0, 3>, <4, 3, 4> pigment { color rgb <0.1, 0.6, 0.2> } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb 0.1 } finish { diffuse 0.2 reflection 0.7 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.3, 0.3, 0.5> } finish { diffuse 0.5 reflection { 0.1, 0.9 falloff 2 } } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.6, 0.1, 0.1> } finish { diffuse 0.6 reflection { 0, 1 fresnel } } interior { ior 1.5 } }
