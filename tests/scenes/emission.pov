// emission.pov: an emissive box is an area light (sampled by area, shadows from it) over a
// floor, with a background.
// render: -W 64 -H 48 --spp 32 --seed 3
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 3, -5> look_at <0, 0.5, 0> angle 50 }
sky_sphere { pigment { color rgb <0.02, 0.02, 0.03> } intensity 1 }
box { <-0.8, 2, -0.8>, <0.8, 2.1, 0.8> material { emission rgb <6, 5.5, 5> } }
sphere { <0, 0.6, 0>, 0.6 material { diffuse { color rgb <0.7, 0.7, 0.2> } } }
plane { y, 0 material { diffuse { color rgb 0.8 } } }
