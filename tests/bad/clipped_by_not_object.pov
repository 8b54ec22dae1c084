sphere { 0, 1 clipped_by { pigment { color rgb 1 } } }
