// POV-Ray's parametric: x, y and z as functions of u and v over a rectangle, clipped by its
// container; max_gradient, accuracy and precompute read and kept
camera { location <0, 3, -5> look_at 0 }
light_source { <5, 10, -10> color rgb 1 }
parametric {
	function { (1 + 0.4 * cos(v)) * cos(u) }
	function { 0.4 * sin(v) }
	function { (1 + 0.4 * cos(v)) * sin(u) }
	<0, 0>, <2 * pi, 2 * pi>
	contained_by { box { -2, 2 } }
	max_gradient 2
	accuracy 0.005
	precompute 10 x, y, z
	pigment { color rgb <1, 0.6, 0.2> }
}
