light_source { <0, 1, 0> color rgb 1 inverse }
