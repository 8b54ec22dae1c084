// glass_ior.pov (bench/pov_cover.sh): clear dielectrics by ior (1.33, 1.5, 2.4: water, glass,
// diamond) and one with interior fade (fade_distance, fade_power 2, fade_color) as absorption,
// written as POV-Ray's physical glass: rgbf / rgbt pigments, no diffuse, Fresnel reflection
// (reflection { 0, 1 fresnel on } conserve_energy: what circe's dielectric does by itself) and
// max_trace_level 20, so that total internal reflection is followed, not cut to black.
#include "glass_stage.inc"
global_settings { max_trace_level 20 }
#declare F = finish { diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
sphere { <-2.7, 1, 0>, 0.9 pigment { rgbf <1, 1, 1, 1> } finish { F } interior { ior 1.33 } }
sphere { <-0.9, 1, 0>, 0.9 pigment { rgbf <0.7, 0.9, 1, 0.9> } finish { F } interior { ior 1.5 } }
sphere { <0.9, 1, 0>, 0.9 pigment { rgbt <1, 1, 1, 1> } finish { F } interior { ior 2.4 } }
sphere { <2.7, 1, 0>, 0.9 pigment { rgbf 1 } finish { F } interior { ior 1.5 fade_distance 0.6 fade_power 2 fade_color <0.9, 0.3, 0.1> } }
