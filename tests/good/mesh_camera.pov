// POV-Ray's mesh_camera, distribution 0: a declared mesh copied by mesh { M } (POV-Ray's), two rays
// per pixel from two meshes (4 faces: the degenerate one is not a face), location z and direction z
#declare M = mesh {
  triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> }
  triangle { <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  triangle { <0, 0, 0>, <1, 1, 0>, <2, 2, 0> }
}
camera {
  mesh_camera { 2 0 0
    mesh { M translate <0, 0, -2> }
    mesh { M scale 2 }
  }
  location <0, 0, 0.01>
  direction <0, 0, -1>
}
sphere { <0, 0, 5>, 1 }
