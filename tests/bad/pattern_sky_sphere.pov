// A sky_sphere takes one colour: a patterned sky is refused.
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } } }
