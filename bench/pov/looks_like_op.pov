// looks_like_op.pov (light19b): a red light in an object pattern's union lights nothing (POV-Ray: 1 light source)
global_settings { assumed_gamma 1 }
camera { location <0, 14, -0.001> look_at 0 angle 60 }
plane { y, 0 pigment { object { union { sphere { 0, 2 } light_source { <3, 4, 0> color rgb <1, 0, 0> } } color rgb 1 color rgb <0, 1, 0> } } finish { ambient 0 diffuse 1 } }
light_source { <0, 10, 0> color rgb 0.5 }
