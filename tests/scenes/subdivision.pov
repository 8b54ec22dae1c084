// subdivision.pov: a Catmull-Clark cube (OpenSubdiv's catmark_cube cage, inline) at level 3 with one
// sharp crease, and a Loop-scheme tetrahedron, under a light.
// render: -W 64 -H 48 --spp 16 --seed 5
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 2, -5> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 5, -4> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb 0.2 } intensity 1 }
subdivision_surface {
  vertex_vectors { 8, <-0.5,-0.5,0.5>, <0.5,-0.5,0.5>, <-0.5,0.5,0.5>, <0.5,0.5,0.5>,
                      <-0.5,0.5,-0.5>, <0.5,0.5,-0.5>, <-0.5,-0.5,-0.5>, <0.5,-0.5,-0.5> }
  faces { 6, <0,1,3,2>, <2,3,5,4>, <4,5,7,6>, <6,7,1,0>, <1,7,5,3>, <6,0,2,4> }
  creases { 1, <2,3>, 10 }
  level 3
  scale 1.5 translate <-1, 0.75, 0>
  material { diffuse { color rgb <0.8, 0.5, 0.3> } }
}
subdivision_surface {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <0.5,0,0.87>, <0.5,0.8,0.29> }
  faces { 4, <0,2,1>, <0,1,3>, <1,2,3>, <2,0,3> }
  scheme loop
  level 3
  scale 2 translate <0.4, 0, -0.5>
  material { diffuse { color rgb <0.3, 0.6, 0.8> } }
}
plane { y, 0 material { diffuse { color rgb 0.6 } } }
