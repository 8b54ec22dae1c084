// magnet takes type 1 or 2.
sphere { 0, 1 pigment { magnet 3 mandel 10 } }
