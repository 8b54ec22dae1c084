// blob_textures.pov (bench/pov_side.sh): a blob's component textures: red on the +x component, blue
// on the -x one, black in the hole its negative cylinder cuts, white (the blob's own) between.
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -5> color 1 }
#declare B = blob { threshold 0.6
  sphere { 0, 1, 1 }
  sphere { x, 1, 1 pigment { rgb <1, 0.1, 0.1> } }
  cylinder { -z*2, z*2, 0.3, -1 translate 0.5*x pigment { rgb 0 } }
  sphere { -x, 1, 1 texture { pigment { rgb <0.1, 0.1, 1> } } }
}
object { B pigment { rgb 1 } }
plane { y, -1 pigment { rgb 0.5 } }
