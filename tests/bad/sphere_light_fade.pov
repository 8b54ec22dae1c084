light_source { <0, 5, 0> color rgb 1 radius 0.5 fade_distance 2 fade_power 2 }
