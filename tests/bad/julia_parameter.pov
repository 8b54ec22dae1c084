julia_fractal { <0.2, 0.1, 0.5> }
