// POV-Ray refuses a color_map with average ("Cannot use color_map with this pattern type").
sphere { 0, 1 pigment { average color_map { [1 rgb 1] [1 rgb 0] } } }
