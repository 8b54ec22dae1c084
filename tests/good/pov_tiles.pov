// POV-Ray's old tiles { texture tile2 texture }: checker with the second texture on entry 0 and
// the first on entry 1; quick_color read and ignored, before and after a pigment's colour.
#declare Wood = texture { pigment { rgb <0.6, 0.4, 0.2> } finish { phong 0.5 } }
plane { y, 0 texture { tiles { texture { pigment { rgb <1, 0, 0> } } tile2 texture { pigment { marble } } } scale 2 } }
sphere { 0, 1 texture { Wood pigment { quick_color red 0.95 green 0.62 } } }
sphere { 0, 1 texture { pigment { rgb 0.5 quick_colour rgb <0, 0, 1> } } }
