// exterior belongs to the fractals.
sphere { 0, 1 pigment { bozo exterior 1, 1 } }
