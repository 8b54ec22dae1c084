camera { location <0, 0, -5> look_at 0 }
sphere { <0, 0, 0>, 1
  translate x
