julia_fractal { <0.2, 0.1, 0.5, -0.2> hypercomplex exp }
