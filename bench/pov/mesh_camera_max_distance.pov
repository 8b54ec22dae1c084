// mesh_camera_max_distance.pov: POV-Ray's mesh_camera max_distance (bench/README.md, light19b): a
// type 3 quad at z = -5; at 5.6 the sphere is cut and the plane (at 9) gone; edit the 5.6 for 0 or 7.
background { rgb <0.1, 0.2, 0.4> }
plane { z, 4 pigment { checker rgb 0.9, rgb 0.1 scale 0.5 } finish { ambient 1 diffuse 0 } }
sphere { <-0.8, 0.3, 1>, 0.6 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
box { <0.6, -1.2, 0>, <1.7, -0.2, 1> rotate z * 20 pigment { rgb <0.1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
camera { mesh_camera { 1 3 5.6 mesh {
  triangle { <-2, -1.5, 0>, <-2, 1.5, 0>, <2, 1.5, 0> uv_vectors <0, 0>, <0, 1>, <1, 1> }
  triangle { <-2, -1.5, 0>, <2, 1.5, 0>, <2, -1.5, 0> uv_vectors <0, 0>, <1, 1>, <1, 0> }
  translate <0, 0, -5>
} } location <0, 0, 0> }
