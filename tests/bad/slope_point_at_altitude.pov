// POV-Ray: altitude cannot be used with point_at in a slope pattern
sphere { 0, 1 pigment { slope { point_at <0, 9, 0> altitude y } } }
