// POV-Ray's mandel and julia patterns (z^2 + c in the x-y plane) with their exterior and
// interior types; mandel's default colour map.
sphere { 0, 1 pigment { mandel 200 } }
sphere { 0, 1 pigment { mandel 50 exterior 6, 0.5 interior 1, 2 color_map { [0 rgb 0] [1 rgb 1] } scale 2 } }
sphere { 0, 1 pigment { julia <0.353, 0.288>, 30 interior 1, 1 exponent 2 } }
sphere { 0, 1 pigment { rgb 0.5 } normal { mandel 20 0.4 } }
// magnet 1 | 2, in mandel's form or julia's; a normal's slope_map (<height, slope> entries)
sphere { 0, 1 pigment { magnet 2 mandel 100 interior 1, 0.5 } }
sphere { 0, 1 pigment { magnet 1 julia <0.3, 0.2>, 40 } }
sphere { 0, 1 pigment { rgb 0.5 } normal { mandel 80 1 interior 1, 5 slope_map { [0 <0, 0>] [0.5, <0.5, 1>] [1 <1, 0>] } } }
