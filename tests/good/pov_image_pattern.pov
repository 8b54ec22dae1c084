// POV-Ray's image_pattern: an image's grey (or alpha) as a pattern value, mapped as image_map;
// the file found beside the scene or, as here, in a -I folder (tests run with -I inc).
sphere { 0, 1 pigment { image_pattern { png "tiny.png" } color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } } }
sphere { 0, 1 pigment { image_pattern { png "tiny.png" map_type 2 interpolate 2 once use_alpha } } }
sphere { 0, 1 pigment { rgb 1 } normal { image_pattern { "tiny.png" use_colour } 0.7 } }
sphere { 0, 1 pigment { image_map { png "tiny.png" } } }
