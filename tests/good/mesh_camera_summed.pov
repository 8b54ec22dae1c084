// POV-Ray's mesh_camera, distribution 1: the faces of both meshes summed in order (3 + 3, the
// degenerate ones not faces), two rays per pixel from faces i and width * height + i
#declare M = mesh {
  triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> }
  triangle { <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  triangle { <0, 0, 0>, <1, 1, 0>, <2, 2, 0> }
  triangle { <1, 1, 0>, <1, 2, 0>, <2, 1, 0> }
}
camera {
  mesh_camera { 2 1
    mesh { M }
    mesh { M scale 2 translate <0, 0, -1> }
  }
  location <0, 0, 0.01>
}
sphere { <0, 0, 5>, 1 }
