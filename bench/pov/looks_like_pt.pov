// looks_like_pt.pov (light19b): a red light in a projected_through's union lights nothing (POV-Ray: 1 light source)
global_settings { assumed_gamma 1 }
camera { location <0, 14, -0.001> look_at 0 angle 60 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 10, 0> color rgb 0.5
  projected_through { union { disc { <0,5,0>, y, 3 } light_source { <3, -6, 0> color rgb <1, 0, 0> } } }
}
