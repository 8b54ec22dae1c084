// sheet.pov: a sheet of skin 3 mm thick (0.8 of skin's red diffuse mean free path, 3.7 mm) and
// 60 mm square, seen slightly from the side with a strong light behind it and a weak one in front:
// the red glow of light through an ear's rim or a web of skin, which every diffusion profile
// loses (its profile is a half space's). Issue 21's thin case.
#version 3.7;
global_settings { mm_per_unit 10 }
camera { location <1.5, 1.0, -8> look_at <0, 0, 0> angle 40 }
light_source { <-1, 1.5, 6> color rgb 1 intensity 300 }
light_source { <2, 2, -8> color rgb 1 intensity 10 }
background { color rgb 0 }
box { <-3, -3, 0>, <3, 3, 0.3> rotate <0, 20, 8> material { skin {} } }
