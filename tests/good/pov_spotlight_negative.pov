// pov_spotlight_negative: POV-Ray keeps a spotlight's radius and falloff as cosines, so a
// negative angle is its opposite: cornell.pov's `radius -90 falloff 90` (a cosine falloff).
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius -90 falloff 90 tightness 1 }
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 20 falloff -30 }
