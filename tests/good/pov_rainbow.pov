// POV-Ray's rainbow: read, checked as POV-Ray checks it, and ignored with a warning.
rainbow {
  angle 42.5 width 5 distance 1.0e7 direction <-0.2, -0.2, 1> jitter 0.01 up y
  arc_angle 120 falloff_angle 30
  colour_map { [0 rgbf <1, 0.5, 1, 1>] [0.5 rgbf <0.2, 1, 0.2, 0.8>] [1 rgbf <1, 0.2, 0.2, 1>] }
}
sphere { 0, 1 pigment { rgb 1 } }
