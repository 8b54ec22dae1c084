// mesh_camera distribution 3 (uv reverse mapping) with smooth: a quad of two smooth triangles
// whose uv cover [0,1]^2 and whose corner normals fan out, so the view widens like a
// perspective camera's (the interpolation kinks along the quad's diagonal, in POV-Ray too).
// circe beside POV-Ray 3.7: bench/pov_side.sh . bench/pov/mesh_camera_uv.pov
#version 3.7;
// Glow alone (ambient 1, no light): flat colours, so the two images differ by the camera only.
global_settings { assumed_gamma 1 }
#declare F = 0.22; // the fan: corner normals <+-F*4/3, +-F, 1>
camera {
  mesh_camera { 1 3
    mesh {
      smooth_triangle { <-2, -1.5, 0>, <-F * 4 / 3, -F, 1>, <-2, 1.5, 0>, <-F * 4 / 3, F, 1>,
                        <2, 1.5, 0>, <F * 4 / 3, F, 1> uv_vectors <0, 0>, <0, 1>, <1, 1> }
      smooth_triangle { <-2, -1.5, 0>, <-F * 4 / 3, -F, 1>, <2, 1.5, 0>, <F * 4 / 3, F, 1>,
                        <2, -1.5, 0>, <F * 4 / 3, -F, 1> uv_vectors <0, 0>, <1, 1>, <1, 0> }
      rotate <20, 0, 0> translate <0, 3, -8>
    }
    smooth
  }
  location <0, 0, 0.001>
}
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.1 } finish { ambient 1 diffuse 0 } }
sphere { <-1.5, 1, 2>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
sphere { <1.2, 0.7, 0>, 0.7 pigment { rgb <0.1, 0.7, 0.2> } finish { ambient 1 diffuse 0 } }
box { <2, 0, 4>, <3.5, 2, 5.5> rotate y * 30 pigment { rgb <0.2, 0.3, 0.9> } finish { ambient 1 diffuse 0 } }
