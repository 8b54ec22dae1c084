// POV-Ray 3.7's light_source items: fade, tightness, cylinder (its defaults), shadowless,
// area_light with its modifiers, and a circe light with intensity beside them.
light_source { <0, 5, 0> color rgb 1 }
light_source { <0, 5, 0> color rgb 1 intensity 25 }
light_source { <1, 6, 2> color rgb <1, 0.5, 0.25> fade_distance 4 fade_power 2 shadowless }
light_source { <0, 8, 0> color rgb 1 spotlight point_at 0 radius 12 falloff 20 tightness 8 }
light_source { <0, 8, 0> color rgb 1 cylinder point_at 0 }
light_source { <0, 8, 0> color rgb 1 cylinder point_at 0 radius 2 falloff 3 tightness 1 }
light_source { <0, 6, 0> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 4, 5 jitter adaptive 1 }
light_source { <0, 6, 0> color rgb 1 area_light x, z, 3, 3 circular orient intensity 36 }
