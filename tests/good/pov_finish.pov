// pov_finish: every item of POV-Ray's finish circe reads (tests/good's IR dump shows what each
// becomes), ambient_light, and constant and ground fogs.
global_settings { assumed_gamma 1 ambient_light rgb <1, 0.9, 0.8> }
fog { distance 40 color rgb <0.6, 0.7, 0.8> }
fog { fog_type 2 distance 10 color rgb 0.9 fog_offset 0.5 fog_alt 2 up <0, 2, 0> rotate <0, 0, 10> }
fog { 25 rgb 0.5 turbulence 0.3 }
#declare Wheat = color red 0.96 green 0.87 blue 0.7;
fog { distance 200 Wheat * .5 } // a declared colour (lights/circular.pov)
#declare Shiny = finish { phong 0.8 phong_size 60 specular 0.3 roughness 0.01 metallic }
sphere { 0, 1 pigment { color rgb <1, 0.2, 0.2> } finish { ambient 0.2 diffuse albedo 0.7 brilliance 1 } }
sphere { 2*x, 1 pigment { color rgb 1 } finish { Shiny reflection { 0.1, 0.6 falloff 2 metallic 0.5 } } }
sphere { 4*x, 1 pigment { color rgb 1 } finish { reflection 0.3 conserve_energy emission rgb <0, 0, 1> } }
sphere { 6*x, 1 texture { pigment { color rgb 0.9 } finish { reflection { 1 fresnel } specular albedo 0.5 phong albedo 0.4 } }
	interior { ior 1.5 } }
sphere { 8*x, 1 pigment { color rgb 0.5 } finish { crand 0.1 irid { 0.3 thickness 0.5 turbulence 0.2 } diffuse 0.6, 0.2
	brilliance 2 metallic 0.5 ambient 0 } }
