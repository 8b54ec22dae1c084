// A finish's subsurface without global_settings { subsurface { } }: POV-Ray renders it as a plain
// finish, and so does circe (warned about once per scene).
sphere { 0, 1 texture { pigment { rgb 0.8 } finish { subsurface { translucency 1 } } } interior { ior 1.3 } }
sphere { x * 3, 1 texture { pigment { rgb 0.7 } finish { subsurface { translucency 2 } } } }
