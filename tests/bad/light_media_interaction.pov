light_source { <0, 5, 0> color rgb 1 media_interaction off }
