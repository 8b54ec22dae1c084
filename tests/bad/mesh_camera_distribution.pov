// distribution types 1 to 3 are POV-Ray's; circe does 0 only, and 4 is no type at all
#declare M = mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } }
camera { mesh_camera { 1 3 mesh { M } } }
sphere { <0, 0, 5>, 1 }
