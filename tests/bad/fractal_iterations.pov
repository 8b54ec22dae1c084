// the iterations limit is at least 1.
sphere { 0, 1 pigment { mandel 0 } }
