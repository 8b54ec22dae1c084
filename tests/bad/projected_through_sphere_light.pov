light_source { <0, 5, 0> color 1 radius 0.5
  projected_through { sphere { 0, 1 } } }
