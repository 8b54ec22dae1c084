light_source { <0, 5, 0> color rgb 1 point_at <0, 0, 0> }
