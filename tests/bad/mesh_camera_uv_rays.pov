// distribution 3 (uv) takes one ray per pixel, as POV-Ray's Parse_Mesh_Camera requires
camera { mesh_camera { 2 3 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> uv_vectors <0, 0>, <0, 1>, <1, 0> } } } }
