// An SSS block's pigment is a pattern: one colour is its 'color'.
sphere { 0, 1 material { wax { pigment { rgb 0.5 } } } }
