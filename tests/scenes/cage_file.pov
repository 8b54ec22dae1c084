// cage_file.pov: subdivision cages read from files, as the files give them - OpenSubdiv's pawn
// (quads, open at its base, creases from its `t crease` tags) in wax, and its creased cube
// (catmark_cube_creases1: eleven sharp edges and one soft one, from the file's tags) - at level 2.
// render: -W 64 -H 48 --spp 16 --seed 7
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 2.2, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 5, -4> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb 0.2 } intensity 1 }
// The shapes are z-up: stand the pawn on its base, centred, twice as tall as the torus.
subdivision_surface {
  file "../../scenes/assets/opensubdiv_shapes/catmark_pawn.obj"
  level 2
  translate <-1.747, 1.275, -0.026> rotate <-90, 0, 0> scale 4 translate <0.9, 0, 0.3>
  material { wax { } }
}
subdivision_surface {
  file "../../scenes/assets/opensubdiv_shapes/catmark_cube_creases1.obj"
  level 2
  rotate <-90, 0, 0> scale 0.55 rotate <0, 20, 0> translate <-1.1, 0.55, 0>
  material { diffuse { color rgb <0.3, 0.6, 0.8> } }
}
plane { y, 0 material { diffuse { color rgb 0.6 } } }
