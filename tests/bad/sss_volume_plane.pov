// The volume method walks inside the object: a plane bounds no volume.
camera { location <0, 1, -4> look_at <0, 0, 0> }
light_source { <0, 5, -5> color rgb 1 }
plane { y, 0 material { marble { method volume } } }
