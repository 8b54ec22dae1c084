// POV-Ray 3.7's finish emission is outside circe, which says what to write instead.
sphere { 0, 1 finish { emission 1 diffuse 0 } }
