// smooth (interpolated normals) is for distribution 3 only, as in POV-Ray
camera { mesh_camera { 1 1 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } smooth } }
