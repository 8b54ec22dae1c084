// default: #default { texture | pigment | finish } with POV-Ray 3.7's semantics (checked against
// povray 3.7.0 by rendering): every texture made after it starts from the default texture, and an
// object placed at the top level without a texture takes the default current at its placing.
#declare Early = box { 0, 1 }                      // declared before any #default, placed after
sphere { 0, 1 }                                    // before any #default: circe's own default
#default { finish { diffuse 0.9 } }
#declare T = texture { pigment { rgb <0, 1, 0> } } // takes the default finish when made
#default { pigment { rgb <1, 0, 0> } }
#default { finish { diffuse 0.5 } }                // later textures only: T keeps diffuse 0.9
sphere { 1, 1 texture { T } }                      // green, diffuse 0.9
sphere { 2, 1 }                                    // the default: red, diffuse 0.5
sphere { 3, 1 finish { specular 0.5 } }            // a bare finish starts from the default: red
object { Early }                                   // the default at its placing: red
union {
  sphere { 4, 1 }                                  // the union's pigment
  sphere { 5, 1 pigment { rgb 1 } }                // its own
  pigment { rgb <0, 0, 1> }
}
#default { texture { T } }
sphere { 6, 1 }                                    // T itself
default { pigment { rgb <0, 0, 1> } }              // the old form without '#', a statement
sphere { 7, 1 pigment { } }                        // an empty pigment: the default's, blue
