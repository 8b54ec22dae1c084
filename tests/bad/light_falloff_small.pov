light_source { <0, 5, 0> color rgb 1 spotlight radius 40 falloff 20 point_at 0 }
