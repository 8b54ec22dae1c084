// POV-Ray's translucency is 1 / sigma_s' in mm: a channel of 0 or below is no medium.
global_settings { subsurface { } }
sphere { 0, 1 texture { pigment { rgb 0.8 } finish { subsurface { translucency <1, -0.5, 1> } } } }
