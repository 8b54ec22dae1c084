// POV-Ray's density_file df3 pattern: the voxels (8-bit here) on the unit cube, interpolate
// 0 (the default), 1 trilinear, 2 tricubic; in a pigment, a normal and a media density.
sphere { 0, 1 pigment { density_file df3 "data/tiny.df3" color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 pigment { density_file df3 "data/tiny.df3" interpolate 1 translate -0.5 } }
sphere { 0, 1 pigment { rgb 1 } normal { density_file df3 "data/tiny.df3", 0.5 interpolate 2 } }
box { -1, 1 hollow pigment { rgbt 1 } interior { media { scattering { 1, 0.5 } density { density_file df3 "data/tiny.df3" interpolate 1 } } } }
