// distribution 3 maps each pixel to the mesh's uv: a mesh without uv_vectors has uv 0 at every
// corner, no face of an area in uv (POV-Ray's barycentrics 0 / 0), so no pixel could get a ray
#declare M = mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } }
camera { mesh_camera { 1 3 mesh { M } } }
sphere { <0, 0, 5>, 1 }
