// magnet is followed by mandel or julia.
sphere { 0, 1 pigment { magnet 1 bozo } }
