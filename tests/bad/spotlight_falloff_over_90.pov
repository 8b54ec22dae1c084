light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 50 falloff 100 }
