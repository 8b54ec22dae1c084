// Cameras: an orthographic camera sized by right and up, rotated by a camera transform, with a
// thin lens focused on the middle ball: the near and far balls blur, the middle one stays sharp,
// and parallel edges stay parallel (no perspective).
// render: -W 64 -H 48 --spp 32 --seed 8
// compare: --fail 0.05 --fail-percent 1
camera {
  orthographic
  location <0, 1, -6> look_at <0, 0.5, 0>
  right 6*x up 4.5*y
  aperture 0.6 focal_point <0, 0.5, 0> blur_samples 64 confidence 0.9 variance 0.001
  rotate <0, -20, 0>
}
light_source { <-3, 5, -4> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb 0.3 } intensity 1 }
plane { y, 0 material { diffuse { color rgb 0.7 } } }
#declare Ball = sphere { <0, 0.5, 0>, 0.5 }
object { Ball translate <-1.8, 0, -2.5> material { diffuse { color rgb <0.8, 0.3, 0.2> } } }
object { Ball material { diffuse { color rgb <0.3, 0.7, 0.3> } } }
object { Ball translate <1.8, 0, 2.5> material { diffuse { color rgb <0.2, 0.3, 0.8> } } }
box { <-0.2, 0, -0.2>, <0.2, 2, 0.2> translate <1, 0, 0> material { diffuse { color rgb 0.9 } } }
