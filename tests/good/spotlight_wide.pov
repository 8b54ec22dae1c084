// A spotlight wider than a half-space (laser.pov's falloff 100 and 250): POV-Ray keeps the cosine, so
// 250 is 110; nothing behind the light is lit (tests/render/test_light.c checks the falloff).
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 50 falloff 100 }
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius -30 falloff 250 }
