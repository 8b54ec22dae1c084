// meshes.pov: the Stanford bunny from an OBJ file instanced three times (one mesh, one BVH), a
// mesh2 with per-vertex normals, and a thin-lens camera focused on the middle bunny.
// render: -W 64 -H 48 --spp 32 --seed 6
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 aperture 0.15 focal_point <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb 0.3 } intensity 1 }
#declare Bunny = mesh { file "../../scenes/assets/bunny/bunny_npm.obj" }
object { Bunny scale 0.1 translate <-1.5, 0, 1> material { diffuse { color rgb 0.8 } } }
object { Bunny scale 0.1 translate <0, 0, 0> material { diffuse { color rgb <0.9, 0.6, 0.5> } } }
object { Bunny scale 0.1 rotate <0, 90, 0> translate <1.5, 0, 1> material { diffuse { color rgb 0.8 } } }
mesh2 {
  vertex_vectors { 4, <-3, 0, -2>, <3, 0, -2>, <3, 0, 4>, <-3, 0, 4> }
  normal_vectors { 4, <0, 1, 0>, <0, 1, 0>, <0, 1, 0>, <0, 1, 0> }
  face_indices { 2, <0, 2, 1>, <0, 3, 2> }
  material { diffuse { color rgb 0.5 } }
}
