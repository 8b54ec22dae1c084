// anim.pov: a sphere that crosses the frame as clock runs from 0 to 1 (the farm's frame tests).
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 4, -3> color rgb 1 intensity 20 }
background { color rgb 0.3 }
sphere { <clock * 2 - 1, 0.5, 0>, 0.4 material { diffuse { color rgb <0.9, 0.4, 0.2> } } }
plane { y, 0 material { diffuse { color rgb 0.6 } } }
