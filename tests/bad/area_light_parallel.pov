light_source { <0, 5, 0> color rgb 1 parallel point_at 0 area_light x, z, 2, 2 }
