// mesh_camera distribution 1 (summed meshes), one ray per pixel: the image's upper half from
// the faces of a first mesh, its lower half from a second (pixel i is face i of the two in
// order), each an orthographic grid of one small face a pixel, the second turned 25 degrees.
// circe beside POV-Ray 3.7: bench/pov_side.sh . bench/pov/mesh_camera_summed.pov
#version 3.7;
// Glow alone (ambient 1, no light): flat colours, so the two images differ by the camera only.
global_settings { assumed_gamma 1 }
#declare W = image_width; #declare H = image_height;
#declare E = 0.2 * 4 / W;
// rows J0 to J1 - 1 of an orthographic 4 x 3 screen, a face a pixel (centroid at the pixel's
// centre, POV-Ray's normal cross(P3 - P1, P2 - P1) along +z)
#macro Rows(J0, J1)
  mesh {
    #local J = J0;
    #while (J < J1)
      #local I = 0;
      #while (I < W)
        #local C = <-2 + 4 * (I + 0.5) / W, 1.5 - 3 * (J + 0.5) / H, 0>;
        triangle { C + <-E, -E, 0>, C + <-E, 2 * E, 0>, C + <2 * E, -E, 0> }
        #local I = I + 1;
      #end
      #local J = J + 1;
    #end
  }
#end
#declare Upper = Rows(0, H / 2)
#declare Lower = Rows(H / 2, H)
camera {
  mesh_camera { 1 1
    mesh { Upper rotate <20, 0, 0> translate <0, 3, -8> }
    mesh { Lower rotate <20, 25, 0> translate <0, 3, -8> }
  }
  location <0, 0, 0.001>
}
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.1 } finish { ambient 1 diffuse 0 } }
sphere { <-1.5, 1, 2>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
sphere { <1.2, 0.7, 0>, 0.7 pigment { rgb <0.1, 0.7, 0.2> } finish { ambient 1 diffuse 0 } }
box { <2, 0, 4>, <3.5, 2, 5.5> rotate y * 30 pigment { rgb <0.2, 0.3, 0.9> } finish { ambient 1 diffuse 0 } }
