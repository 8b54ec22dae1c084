// a quartic clipped by a plane alone is still unbounded (a half-space bounds one side of one axis)
camera { location <0, 0, -5> look_at 0 }
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1>
	sturm
	clipped_by { plane { z, 1 } }
}
