// a fractal's exponent belongs to mandel and julia (POV-Ray's magnets have none)
sphere { 0, 1 pigment { magnet 1 mandel 20 exponent 3 } }
