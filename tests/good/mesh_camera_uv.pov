// POV-Ray's mesh_camera, distribution 3: a quad whose uv cover [0,1]^2, smooth (its second
// triangle's normals differ), max_distance 0; the second mesh is ignored with a warning
camera {
  mesh_camera { 1 3 0
    mesh {
      triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> }
      smooth_triangle { <-1, -1, 0>, <0, 0, 1>, <1, 1, 0>, <0, 0, 1>, <-1, 1, 0>, <0, 0.1, 1>
        uv_vectors <0, 0>, <1, 1>, <0, 1> }
      translate <0, 0, -3>
    }
    mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> uv_vectors <0, 0>, <0, 1>, <1, 0> } }
    smooth
  }
  location <0, 0, 0.01>
}
sphere { <0, 0, 5>, 1 }
