light_source { <0, 5, 0> color rgb 1 cylinder point_at 0 radius 2 falloff 1 }
