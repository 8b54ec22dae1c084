// farm.pov: the small scene the farm tests render whole and in tiles.
global_settings { max_trace_level 4 }
camera { location <0, 1.2, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <3, 5, -3> color rgb 1 intensity 30 }
background { color rgb <0.2, 0.3, 0.4> }
sphere { <0, 0.6, 0>, 0.6 material { diffuse { color rgb <0.8, 0.3, 0.2> } } }
sphere { <1.1, 0.3, 0.4>, 0.3 material { diffuse { color rgb <0.2, 0.6, 0.3> } } }
plane { y, 0 material { diffuse { color rgb 0.7 } } }
