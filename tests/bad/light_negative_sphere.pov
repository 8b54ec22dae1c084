light_source { <0, 5, 0> color rgb <1, -1, 1> radius 0.5 }
