box { 0, 1 pigment { rgbt 1 } hollow
  interior { media { scattering { 6, rgb 0.5 } } }
}
