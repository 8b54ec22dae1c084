#declare M = material { skin { } }
sphere { 0, 1 texture { M pigment { rgb 1 } } }
