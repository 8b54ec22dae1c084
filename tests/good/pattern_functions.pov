// pattern_functions: `function { pattern {...} }` and `function { pigment {...} }` evaluated (the
// pattern's value after its warps and wave; the pigment's five components and .gray), and the
// function pattern in a pigment, a normal and a media's density, evaluated at the shading point.
// pattern_functions.stderr is what povray 3.7.0 printed for the #debug lines of this file.
#declare G = function { pattern { gradient x } }
#declare O = function { pattern { onion scale 2 } }
#declare C = function { pattern { checker } }
#declare L = function { pattern { leopard } }
#declare W = function { pattern { gradient y triangle_wave frequency 2 } }
#declare Sp = function { pattern { spherical translate <1, 0, 0> } }
#debug concat(str(G(0.3, 0, 0), 0, 6), " ", str(G(1.25, 0, 0), 0, 6), " ", str(G(-0.3, 0, 0), 0, 6), "\n")
#debug concat(str(O(0.6, 0.8, 0), 0, 6), " ", str(C(0.5, 0.5, 0.5), 0, 0), str(C(1.5, 0.5, 0.5), 0, 0), "\n")
#debug concat(str(L(0.4, 1.1, -2), 0, 6), " ", str(W(0, 0.2, 0), 0, 6), " ", str(Sp(1.3, 0.4, 0), 0, 6), "\n")
#declare P = function { pigment { gradient x color_map { [0 rgbft <1, 0, 0, 0.2, 0.1>] [1 rgbft <0, 0, 1, 0.4, 0.3>] } } }
#declare Q = function { P(x, y, z).gray * 2 + P(x, y, z).transmit }
#debug concat(str(P(0.25, 0, 0).red, 0, 6), " ", str(P(0.25, 0, 0).blue, 0, 6), " ", str(P(0.25, 0, 0).filter, 0, 6), " ", str(Q(0.25, 0, 0), 0, 6), "\n")
#declare Pc = P(0.5, 0, 0);
#debug concat(vstr(5, Pc, ", ", 0, 4), "\n")
// a pigment function of a function pattern calling a spline (splinefunction.pov's way)
#declare Spl = function { spline { linear_spline 0, <0, 0, 0> 1, <1, 0.5, 0> } }
#declare Ps = function { pigment { function { Spl(x).y } color_map { [0 rgb 0] [1 rgb 1] } } }
#debug concat(str(Ps(0.5, 0, 0).gray, 0, 6), "\n")
#declare F = function { x*0.5 + 0.25 }
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, 1 pigment { function { F(x, y, z) } color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } } }
plane { y, -1 pigment { function { abs(y) } } normal { function { G(x, y, z) } 0.3 } }
box { -1, 1 translate 3*x pigment { rgbt 1 } hollow
	interior { media { absorption 1 density { function { min(1, max(0, y)) } } } } }
