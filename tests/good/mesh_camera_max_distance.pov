// POV-Ray's mesh_camera max_distance: the camera ray's first hit is sought only that far (the
// dump's "max_distance 7.5"; tests/render/mesh_camera.sh renders one). mesh_camera_no_distance.pov:
// the values POV-Ray takes as no limit.
camera { mesh_camera { 1 0 7.5 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } } }
sphere { <0, 0, 5>, 1 }
