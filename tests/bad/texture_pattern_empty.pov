// A patterned texture needs its textures.
sphere { 0, 1 texture { checker scale 2 } }
