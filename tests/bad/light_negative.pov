light_source { <0, 5, 0> color -0.9 }
