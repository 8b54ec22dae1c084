// media.pov: POV-Ray's media in containers (doc/language.md "Media"): a box of scattering haze
// (Henyey-Greenstein, forward) with a coloured absorption, a sphere of emitting glow whose
// density is a spherical pattern through a density_map, and a glass ball (ior 1.3) holding an
// isotropic scattering medium; shadows are attenuated by the media they cross.
// render: -W 64 -H 48 --spp 16 --seed 5
// compare: --fail 0.08 --fail-percent 2
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 1, 0> angle 50 }
light_source { <4, 8, -5> color rgb 1.2 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.25 } }
box { <-3.2, 0, -1>, <-1.2, 2, 1>
  pigment { rgbt 1 } hollow
  interior { media { scattering { 5, rgb 0.8 eccentricity 0.5 } absorption rgb <0.05, 0.25, 0.5> } }
}
sphere { 0, 1
  pigment { rgbt 1 } hollow
  interior { media { emission rgb <1, 0.6, 0.2>
    density { spherical density_map { [0 rgb 0] [0.6 rgb 0.5] [1 rgb 1] } } } }
  scale 0.9 translate <0, 1, 0>
}
sphere { <2.2, 1, 0>, 1
  pigment { rgbf 1 } finish { specular 0 }
  interior { ior 1.3 media { scattering { 1, rgb 1.5 } } }
}
