// #default takes texture, pigment, finish and normal (POV-Ray 3.7's Parse_Default); not an interior.
#default { interior { ior 1.5 } }
