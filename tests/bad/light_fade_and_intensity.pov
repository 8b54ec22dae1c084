light_source { <0, 5, 0> color rgb 1 fade_distance 3 fade_power 2 intensity 4 }
