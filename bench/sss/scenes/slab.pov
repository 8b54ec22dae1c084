// slab.pov: a flat marble slab, 30 mm thick, lit uniformly from above by a distant light and
// nothing else, seen from above at an angle. Circle tracing's best case: on a plane, R(r)/p_A is
// constant (zero variance for a grey profile; marble's channels differ, so not quite zero here).
#version 3.7;
global_settings { mm_per_unit 10 }
camera { location <0, 2.5, -2.5> look_at <0, 0, 0> angle 40 }
light_source { <1, 8, -3> color rgb 1 intensity 0.8 parallel point_at <0, 0, 0> }
background { color rgb 0 }
box { <-20, -3, -20>, <20, 0, 20> material { marble {} } }
