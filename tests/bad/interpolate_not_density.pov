// interpolate is density_file's
sphere { 0, 1 pigment { bozo interpolate 1 } }
