box { 0, 1 pigment { rgbt 1 } hollow
  interior { media { scattering { 5, rgb 0.5 eccentricity 1 } } }
}
