// distribution types 1 and 3 are POV-Ray's (summed meshes, uv baking); circe does 0 and 2 only
#declare M = mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } }
camera { mesh_camera { 1 3 mesh { M } } }
sphere { <0, 0, 5>, 1 }
