// lips.pov: a lips-like fold, two skin ellipsoids (30 x 7 x 12 mm) facing each other across a
// 0.4 mm gap, one SSS volume (group "lips"): circles from one lip reach the other, which the leak
// filter must hold back. Lit from above and in front.
#version 3.7;
global_settings { mm_per_unit 10 }
camera { location <0.6, 0.5, -4> look_at <0, 0, 0> angle 40 }
light_source { <-2, 5, -4> color rgb 1 intensity 25 }
background { color rgb 0 }
#declare Lip = sphere { <0, 0, 0>, 1 scale <1.5, 0.35, 0.6> }
object { Lip translate <0, 0.37, 0> material { skin { group "lips" } } }
object { Lip translate <0, -0.37, 0> material { skin { group "lips" } } }
