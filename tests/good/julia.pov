// POV-Ray's julia_fractal: quaternion or hypercomplex, sqr or cube, max_iteration, precision and
// slice (fractal1.pov .. fractal4.pov)
camera { location <0, 0, -4> look_at 0 }
light_source { <5, 10, -10> color rgb 1 }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
	pigment { color rgb 1 } translate -x }
julia_fractal { <0.2, 0.1, 0.59, -0.2> max_iteration 7 precision 30 cube hypercomplex
	slice <0, 0, 1, 1>, 0.1 pigment { color rgb 1 } scale 0.5 translate x }
