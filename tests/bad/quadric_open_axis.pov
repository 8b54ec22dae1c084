// an infinite cylinder along x intersected with a plane across y: x is still unbounded
camera { location <0, 0, -5> look_at 0 }
intersection {
	quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	plane { y, 0.5 }
}
