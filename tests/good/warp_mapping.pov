// POV-Ray's mapping warps (planar, cylindrical, spherical, toroidal, cubic) seen through pattern
// functions of gradients along x, y and z (scaled by 10: the warped point's coordinates over 10,
// their fractional parts as the ramp wave gives them), at four points each. warp_mapping.stderr
// is POV-Ray 3.7.0's output.
#macro Probe(Name, Fx, Fy, Fz)
  #local I = 0;
  #while (I < 4)
    #local P = <0.3 + 0.7*I, -0.4 + 0.5*I, 0.8 - 0.6*I>;
    #debug concat(Name, ": ", str(Fx(P.x, P.y, P.z), 0, 4), " ", str(Fy(P.x, P.y, P.z), 0, 4), " ",
                  str(Fz(P.x, P.y, P.z), 0, 4), "\n")
    #local I = I + 1;
  #end
#end
#declare Fx = function { pattern { gradient x scale 10 warp { planar } } }
#declare Fy = function { pattern { gradient y scale 10 warp { planar } } }
#declare Fz = function { pattern { gradient z scale 10 warp { planar } } }
Probe("planar", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { planar y, 0.3 } } }
#declare Fy = function { pattern { gradient y scale 10 warp { planar y, 0.3 } } }
#declare Fz = function { pattern { gradient z scale 10 warp { planar y, 0.3 } } }
Probe("planar y 0.3", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { cylindrical } } }
#declare Fy = function { pattern { gradient y scale 10 warp { cylindrical } } }
#declare Fz = function { pattern { gradient z scale 10 warp { cylindrical } } }
Probe("cylindrical", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { cylindrical orientation x dist_exp 1 } } }
#declare Fy = function { pattern { gradient y scale 10 warp { cylindrical orientation x dist_exp 1 } } }
#declare Fz = function { pattern { gradient z scale 10 warp { cylindrical orientation x dist_exp 1 } } }
Probe("cylindrical x dist_exp 1", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { spherical } } }
#declare Fy = function { pattern { gradient y scale 10 warp { spherical } } }
#declare Fz = function { pattern { gradient z scale 10 warp { spherical } } }
Probe("spherical", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { spherical orientation y dist_exp 0.5 } } }
#declare Fy = function { pattern { gradient y scale 10 warp { spherical orientation y dist_exp 0.5 } } }
#declare Fz = function { pattern { gradient z scale 10 warp { spherical orientation y dist_exp 0.5 } } }
Probe("spherical y dist_exp 0.5", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { toroidal } } }
#declare Fy = function { pattern { gradient y scale 10 warp { toroidal } } }
#declare Fz = function { pattern { gradient z scale 10 warp { toroidal } } }
Probe("toroidal", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { toroidal major_radius 2 dist_exp 1 } } }
#declare Fy = function { pattern { gradient y scale 10 warp { toroidal major_radius 2 dist_exp 1 } } }
#declare Fz = function { pattern { gradient z scale 10 warp { toroidal major_radius 2 dist_exp 1 } } }
Probe("toroidal major 2 dist 1", Fx, Fy, Fz)
#undef Fx #undef Fy #undef Fz
#declare Fx = function { pattern { gradient x scale 10 warp { cubic } } }
#declare Fy = function { pattern { gradient y scale 10 warp { cubic } } }
#declare Fz = function { pattern { gradient z scale 10 warp { cubic } } }
Probe("cubic", Fx, Fy, Fz)
sphere { 0, 1 }
