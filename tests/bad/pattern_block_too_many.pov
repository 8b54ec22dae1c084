// checker takes two colours.
sphere { 0, 1 pigment { checker rgb 0, rgb 1, rgb 0.5 } }
