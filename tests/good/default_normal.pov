// default_normal: #default { normal } as POV-Ray 3.7 (Parse_Default: the default texture's
// tnormal): textures made after it start from it, so a texture { pigment } keeps the bumps, a
// texture with a normal of its own replaces them, and an object without a texture takes it.
sphere { 0, 1 }                                    // before: no normal
#default { normal { bumps 0.4 scale 0.2 } }
sphere { 1, 1 }                                    // the default: bumps 0.4
sphere { 2, 1 pigment { rgb <1, 0, 0> } }          // red, with the default's bumps
sphere { 3, 1 normal { dents 0.7 } }               // its own normal
#default { finish { diffuse 0.3 } }                // a later #default item keeps the normal
sphere { 4, 1 }                                    // bumps 0.4, diffuse 0.3
