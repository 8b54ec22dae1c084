light_source { <0, 5, 0> color 1 projected_through { pigment { rgb 1 } } }
