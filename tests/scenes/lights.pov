// lights.pov: a point, a spot, a parallel and a sphere light on diffuse and POV-Ray-finish objects.
// render: -W 64 -H 48 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <-3, 4, -2> color rgb <1, 0.9, 0.8> intensity 12 }
light_source { <3, 5, -1> color rgb <0.4, 0.6, 1> intensity 40 spotlight point_at <1, 0, 0> radius 15 falloff 25 }
light_source { <0, 10, -10> color rgb 0.3 parallel point_at <0, 0, 0> }
light_source { <0, 3, 3> color rgb <1, 0.5, 0.3> intensity 10 radius 0.4 }
plane { y, 0 material { diffuse { color rgb 0.6 } } }
sphere { <-1, 0.7, 0>, 0.7 material { diffuse { color rgb <0.9, 0.9, 0.9> } } }
box { <0.4, 0, -0.5>, <1.6, 1.2, 0.7>
      texture { pigment { color rgb <0.2, 0.5, 0.8> } finish { diffuse 0.8 specular 0.4 roughness 0.02 } } }
