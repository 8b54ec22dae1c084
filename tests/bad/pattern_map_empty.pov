// A color_map needs an entry.
sphere { 0, 1 pigment { bozo color_map { } } }
