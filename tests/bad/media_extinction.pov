box { 0, 1 pigment { rgbt 1 }
  interior { media { scattering { 1, rgb 1 extinction -1 } } }
}
