// POV-Ray's normal forms: a block pattern's list of normals, #default's normal without a
// pattern (its bump_size for the normals after it), uv_mapping before a pattern.
#default { normal { bump_size 1.5 } }
box { -1, 1 normal { checker normal { marble turbulence 0.5 } normal { radial sine_wave frequency 10 } } }
box { -1, 1 normal { hexagon normal { bumps } normal { dents 0.2 } normal { wrinkles } scale 0.5 } }
sphere { 0, 1 normal { bumps scale 0.2 } }
sphere { 0, 1 pigment { uv_mapping spiral2 8 color_map { [0.5 rgb 0] [0.5 rgb 1] } } }
