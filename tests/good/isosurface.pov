// POV-Ray's isosurface: a function, its container (box or sphere), threshold, open and the ray
// marcher's settings (kept in the dump)
#declare F = function { x * x + y * y + z * z }
camera { location <0, 1, -5> look_at 0 }
light_source { <5, 10, -10> color rgb 1 }
isosurface {
	function { sqrt(x * x + y * y + z * z) - 1 }
	contained_by { box { <-1.2, -1.2, -1.2>, <1.2, 1.2, 1.2> } }
	accuracy 0.01
	max_gradient 2
	pigment { color rgb <1, 0.5, 0.2> }
}
isosurface {
	function { F(x, y, z) }
	threshold 0.5
	contained_by { sphere { <0, 0, 0>, 0.6 } }
	evaluate 1, 10, 0.99
	open
	max_trace 4
	translate 2 * x
	pigment { color rgb 1 }
}
isosurface {
	function { y }
	all_intersections
	translate -2 * x
	pigment { color rgb 1 }
}
