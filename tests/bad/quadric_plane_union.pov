// a quadric that is a plane (y < 0), in a union with a sphere: nothing bounds it
camera { location <0, 0, -5> look_at 0 }
union {
	sphere { 0, 1 }
	quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, 0 }
}
