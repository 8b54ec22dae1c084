// A word the finish's subsurface block does not know.
sphere { 0, 1 texture { pigment { rgb 0.8 } finish { subsurface { translucency 1 radius 2 } } } }
