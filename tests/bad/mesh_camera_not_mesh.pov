#declare S = sphere { <0, 0, 0>, 1 }
camera { mesh_camera { 1 0 mesh { S } } }
