// a light_source takes one looks_like.
light_source { 0 color rgb 1 looks_like { sphere { 0, 1 } } looks_like { sphere { 0, 2 } } }
