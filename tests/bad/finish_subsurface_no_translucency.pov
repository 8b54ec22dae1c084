// A finish's subsurface without its translucency (POV-Ray's default 0 divides by zero).
global_settings { subsurface { } }
sphere { 0, 1 texture { pigment { rgb 0.8 } finish { subsurface { anisotropy 0.2 } } } }
