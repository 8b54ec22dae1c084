light_source { <0, 5, 0> color rgb 1 projected_through { sphere { 0, 1 } } }
