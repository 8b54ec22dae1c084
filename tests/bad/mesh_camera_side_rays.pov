// distribution 2 (side-by-side cameras) shoots one ray per pixel, as in POV-Ray
camera { mesh_camera { 2 2 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } } }
