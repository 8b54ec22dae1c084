// POV-Ray divides by the weights' sum: it must be more than 0.
sphere { 0, 1 pigment { average pigment_map { [0 rgb 1] [0 rgb 0] } } }
