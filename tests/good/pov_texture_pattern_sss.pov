// A patterned texture whose entries differ in their finish, one with POV-Ray's subsurface: circe
// derives one medium a material, so every entry takes the first entry's finish and subsurface,
// and says so (doc/language.md "Patterned textures").
global_settings { mm_per_unit 10 subsurface { } }
#declare Wax = texture { pigment { rgb <0.9, 0.8, 0.6> } finish { diffuse 0.8 subsurface { translucency <1, 0.8, 0.6> } } }
#declare Shiny = texture { pigment { rgb 0.2 } finish { diffuse 0.4 phong 1 } }
sphere { 0, 1 texture { checker texture { Wax } texture { Shiny } scale 0.3 } interior { ior 1.4 } }
