// interior_texture: read as a texture body (a declared one, or pigment and finish) and ignored,
// warned about once.
#declare T = texture { pigment { rgb <1, 0, 0> } }
sphere { 0, 1 pigment { rgb 1 } interior_texture { T } }
sphere { x, 1 pigment { rgb 1 } interior_texture { pigment { rgb 0.5 } finish { diffuse 0.2 } } }
