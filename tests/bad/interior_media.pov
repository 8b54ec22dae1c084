sphere { 0, 1 pigment { rgbf <1, 1, 1, 1> } interior { media { absorption 1 } } }
