// A declared color_map is not a pigment_map.
#declare M = color_map { [0 rgb 0] [1 rgb 1] }
sphere { 0, 1 pigment { gradient y pigment_map { M } } }
