// pov_functions_scene: functions.inc, math.inc and transforms.inc parse, and their functions and
// the macros that build or call functions work (pov_functions_scene.stderr: what povray 3.7.0 printed).
#version 3.7;
#include "functions.inc"
#include "math.inc"
#include "transforms.inc"
#debug concat(str(f_sphere(1, 2, 2, 1), 0, 6), " ", str(f_torus(2, 0.5, 0, 1.5, 0.25), 0, 6), " ", str(f_r(1, 2, 3), 0, 6), "\n")
#debug concat(str(f_th(1, 2, 3), 0, 6), " ", str(f_ph(1, 2, 3), 0, 6), " ", str(f_ellipsoid(1, 2, 3, 0.5, 0.25, 2), 0, 6), "\n")
#debug concat(str(f_rounded_box(1.2, 0.3, -2, 0.1, 1, 1, 1), 0, 6), " ", str(f_superellipsoid(0.3, 0.4, 0.5, 0.5, 0.8), 0, 6), "\n")
#debug concat(str(f_paraboloid(0.2, 0.3, 0.1, 2), 0, 6), " ", str(f_torus2(0.5, 0.2, 0.4, 1, 0.8, 0.3), 0, 6), " ", str(f_heart(0.2, 0.3, 0.4, 1), 0, 6), " ", str(f_quartic_cylinder(0.2, 0.5, 0.3, 1, 0.7, 0.6), 0, 6), "\n")
#debug concat(str(f_sine_wave(0.3, 2, 1.5), 0, 6), " ", str(f_scallop_wave(0.3, -2, 1.5), 0, 6), "\n")
// math.inc's functions and the macros that use them
#debug concat(str(sind(30), 0, 6), " ", str(atan2d(1, 1), 0, 6), " ", str(even(4), 0, 0), str(odd(4), 0, 0), " ", str(sgn(-2), 0, 0), " ", str(clip(5, 0, 3), 0, 0), " ", str(clamp(5, 0, 3), 0, 0), " ", str(f_sqr(3), 0, 0), "\n")
#debug concat(str(max3(1, 5, 2), 0, 0), str(min3(4, 5, 2), 0, 0), " ", str(VMin(<3, 1, 2>), 0, 0), str(VMax(<3, 1, 2>), 0, 0), " ", str(Interpolate(0.5, 0, 1, 10, 20, 1), 0, 4), "\n")
#declare Sph = function { f_sphere(x, y, z, 1) }
#declare Grad = fn_Gradient(Sph)
#debug concat(str(Grad(0.3, 0.4, 0.5), 0, 4), " ", str(Gradient_Length(Sph, <1, 2, 3>), 0, 4), " ", vstr(3, vGradient(Sph, <0, 2, 0>), ",", 0, 4), "\n")
// transforms.inc's vtransform and vinv_transform: function { transform { } }
#declare Tr = transform { rotate <0, 0, 90> translate <1, 2, 3> }
#debug concat(vstr(3, vtransform(<1, 0, 0>, Tr), ",", 0, 4), " ", vstr(3, vinv_transform(<1, 3, 3>, Tr), ",", 0, 4), "\n")
#debug concat(vstr(3, vtransform(<1, 2, 3>, Axis_Rotate_Trans(<0, 1, 0>, 90)), ",", 0, 4), "\n")
