sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } interior { ior -1.5 } }
