// A bare pigment, finish or normal after a declared texture changes a copy of it (POV-Ray's top
// texture layer: biscuit.pov's `texture { Black_Chocolate } normal { bumps 0.3 }`), the declared
// texture unchanged; a texture after a bare pigment lies on it as a layer (POV-Ray's
// Link_Textures: glasschess's `pigment { rgbf 0.9 } texture { Glass }`).
#declare T = texture { pigment { rgb <1, 0, 0> } finish { phong 0.5 } }
sphere { 0, 1 texture { T } normal { bumps 0.3 scale 0.05 } }
sphere { x, 1 texture { T } finish { phong 0.1 } }
sphere { 2*x, 1 texture { T } }
sphere { 3*x, 1 pigment { rgbf <0.9, 0.9, 0.9, 0.5> } texture { pigment { rgbt <0, 0, 1, 0.5> } } }
