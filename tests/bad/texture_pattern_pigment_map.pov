// A patterned texture takes a texture_map, not a pigment_map.
sphere { 0, 1 texture { gradient y pigment_map { [0 rgb 0] [1 rgb 1] } } }
