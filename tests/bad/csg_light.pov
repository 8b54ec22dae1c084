// POV-Ray lets a light_source stand in a CSG block, moved with it; circe refuses it by name.
union { sphere { 0, 1 } light_source { <0, 5, 0> color rgb 1 } translate x }
