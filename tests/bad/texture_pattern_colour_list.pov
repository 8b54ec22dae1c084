// A patterned texture's list holds textures, not colours.
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } rgb 0 } }
