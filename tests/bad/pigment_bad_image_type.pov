sphere { 0, 1 texture { pigment { image_map { gif "a.gif" } } } }
