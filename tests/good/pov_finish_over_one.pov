// pov_finish_over_one: POV-Ray takes a finish's diffuse and specular above 1 (lights/soft.pov's
// diffuse 1.5, glasschess.pov's specular 1.5); circe reads them as given, and its BSDF scales the
// lobes' sum down to 1 where it would reflect more than arrives (doc/language.md, Finishes).
sphere { 0, 1 pigment { rgb 1 } finish { diffuse 2 specular 1.5 } }
