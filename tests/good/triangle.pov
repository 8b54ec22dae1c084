// POV-Ray's triangle and smooth_triangle as objects of their own (teapot3.pov, lamppost.pov,
// desk.pov): each a mesh of one triangle, with modifiers, in a union too; and a flat box (a
// two-sided rectangle, with a warning, as POV-Ray renders one)
camera { location <0, 1, -4> look_at 0 }
light_source { <5, 10, -10> color rgb 1 }
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { color rgb <1, 0, 0> } translate x }
union {
	sphere { 0, 0.5 }
	triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
	smooth_triangle { <0, 0, 0>, <0, 0, -1>, <1, 0, 0>, <0, 0, -1>, <0, 1, 0>, <0.2, 0, -1>
		scale 2 }
	pigment { color rgb 1 }
	translate -2 * x
}
box { <-1, -1, 0>, <1, 1, 0> pigment { color rgb 0.5 } translate z }
box { <0, 0, 1>, <1, 0, 1> translate -2 * z }
