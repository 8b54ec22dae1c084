sphere { 0, 1 pigment { rgbt <1, 1, 1, 0.5> }
  interior { ior 1.33 fade_distance 1 fade_power -2 } }
