light_source { <0, 5, 0> color rgb 1 jitter }
cylinder { 0, y, -1 }
