// a light in a union written in a clipped_by: that object is never placed in the scene
sphere { 0, 2 clipped_by { union { light_source { <0, 5, 0> color 1 } box { -1, 1 } } } }
