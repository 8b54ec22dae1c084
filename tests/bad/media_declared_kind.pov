#declare D = density { bozo density_map { [0 rgb 0] [1 rgb 1] } }
box { 0, 1 pigment { rgbt 1 }
  interior { media { emission 1 density { D } } }
}
box { 0, 1 pigment { rgbt 1 } interior { media { D } } }
