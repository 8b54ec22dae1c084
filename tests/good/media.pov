// POV-Ray's media in containers: every item, declared media and densities, two media in one
// interior, a density_map of densities, the lights' media flags.
camera { location <0, 1, -6> look_at <0, 1, 0> }
light_source { <3, 6, -4> color rgb 1 media_interaction off }
light_source { <-3, 6, -4> color rgb 0.5 media_attenuation on media_interaction on }
light_source { <0, 6, 4> color rgb 0.5 media_attenuation off }
#declare Ring = density { spherical ramp_wave density_map { [0 rgb 0] [0.5 rgb <1, 0.5, 0.2>] [1 rgb 1] } }
#declare Plain = density { rgb 0.5 }
#declare Haze = media {
  scattering { 5, rgb 0.3 eccentricity 0.6 extinction 0.5 }
  method 3 intervals 2 samples 4, 8 confidence 0.9 variance 0.001 ratio 0.9 jitter 0.5 aa_level 3 aa_threshold 0.1
}
box { <-1, 0, -1>, <1, 2, 1>
  pigment { rgbt 1 } hollow
  interior {
    media { Haze absorption rgb <0.1, 0.2, 0.3> }
    media { emission 0.2 density { Ring scale 0.8 } density { Plain } translate y }
  }
}
sphere { <2.5, 1, 0>, 1
  pigment { rgbf 1 }
  interior { ior 1.2
    media {
      scattering { 2, 0.4 } scattering { 3, 0.4 }
      density { gradient y density_map { [0 Ring] [1 Plain] } }
    }
    media { scattering { 4, rgb <0.1, 0.2, 0.4> eccentricity 0.3 } }
  }
}
sphere { <-2.5, 1, 0>, 1 pigment { rgbt 1 } interior { media { absorption 0.5 density { bozo } } } }
