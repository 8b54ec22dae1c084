sphere { 0, 1
  texture { pigment { rgb 1 } }
  interior { media { } }
}
