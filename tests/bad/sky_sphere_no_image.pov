sky_sphere { intensity 2 }
