box { 0, 1 pigment { rgbt 1 }
  interior { media { absorption 1 scatering { 1, 1 } } }
}
