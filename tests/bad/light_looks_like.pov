light_source { <0, 5, 0> color rgb 1 looks_like { sphere { 0, 1 } } }
