// pov_sky_normal.pov: a POV-Ray gradient sky with a cloud layer (baked as the environment light),
// normal patterns (bumps, ripples, granite by its slope) and an SSS marble whose agate pigment is
// its albedo, blurred through the medium at circle tracing's entry points. The same file renders
// in POV-Ray 3.7 but for the SSS block, circe's own.
// render: -W 96 -H 64 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 10 }
camera { location <0, 1.6, -6> look_at <0, 1, 0> angle 55 }
light_source { <-6, 9, -8> color rgb 1.2 }
sky_sphere {
	pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.65>] [0.25 rgb <0.3, 0.5, 0.9>] [1 rgb <0.1, 0.2, 0.6>] } }
	pigment { bozo turbulence 0.5 color_map { [0 rgbt <1, 1, 1, 1>] [0.55 rgbt <1, 1, 1, 1>] [0.75 rgb 1] [1 rgb 1] }
		scale <0.4, 0.1, 0.4> }
}
plane { y, 0 pigment { rgb 0.6 } normal { ripples 0.6 frequency 3 } }
sphere { <-2, 1, 0>, 0.9 pigment { rgb <0.8, 0.5, 0.3> } normal { bumps 0.8 scale 0.15 } }
sphere { <0, 1, 0>, 0.9 pigment { rgb <0.4, 0.6, 0.8> } normal { granite 0.4 scale 0.6 } }
sphere { <2, 1, 0>, 0.9 material { marble { color rgb 0.8 radius <3, 2, 1.5> pigment { agate scale 0.4 } } } }
