julia_fractal { <0.2, 0.1, 0.5, -0.2> slice <0, 0, 1, 0>, 0 }
