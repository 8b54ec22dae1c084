// marble is circe's SSS block; as a POV-Ray pattern it is named as not supported.
sphere { 0, 1 pigment { marble turbulence 0.5 } }
