// POV-Ray's average pattern (pigment_map, and a normal's normal_map: entries weighted by
// their values) and crackle's form, metric, offset and solid (doc/language.md "The patterns").
#declare P = pigment { average pigment_map { [1 checker rgb 1 rgb 0 scale 0.2] [3 gradient x] [0.5 rgb <1, 0, 0>] } }
sphere { 0, 1 pigment { P } }
sphere { 0, 1 pigment { average pigment_map { [rgb 1] [2 rgb <0, 0, 1>] } } } // a weight left out is 1
sphere { 0, 1 pigment { crackle form <1, 0, 0> metric 1 offset 0.25 color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 pigment { crackle solid metric <3, 0, 0> } }
sphere { 0, 1 pigment { rgb 0.5 } normal { average normal_map { [bumps 0.5 scale 0.1] [2 gradient x, 0.3] } } }
sphere { 0, 1 pigment { rgb 0.5 } normal { gradient y normal_map { [0 bumps 0.5] [1 dents 0.8] } } }
