light_source { <0, 5, 0> color 1
  projected_through { sphere { 0, 1 } }
  projected_through { box { -1, 1 } } }
