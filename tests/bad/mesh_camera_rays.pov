// distribution 0 shoots ray k of a pixel from mesh k: two rays need two meshes
camera { mesh_camera { 2 0 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } } }
