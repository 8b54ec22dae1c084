// checker takes two textures.
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } texture { pigment { rgb 0.5 } } } }
