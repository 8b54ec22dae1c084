// declared_looks_like.pov (bench/pov_side.sh): a declared lamp whose light has a looks_like bulb,
// placed twice: each copy's bulb sits at its own light, over its own post.
global_settings { assumed_gamma 1 }
camera { location <0, 4, -12> look_at <0, 2, 0> angle 50 }
plane { y, 0 pigment { rgb 0.7 } finish { ambient 0 } }
#declare Lamp = union {
  light_source { <0, 3, 0> color 1 looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } } } }
  cylinder { 0, <0, 2.6, 0>, 0.1 pigment { rgb 0.5 } finish { ambient 0 } }
}
object { Lamp translate x * -3 }
object { Lamp translate x * 3 }
