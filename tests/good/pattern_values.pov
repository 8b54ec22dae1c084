// pattern_values: every pattern issue 18 names, through `function { pattern {...} }` at eight
// points (off the lattice, negative coordinates too): the value after the pattern's own
// turbulence, warps, transforms and wave, four to a line (POV-Ray wraps its messages at 80).
// pattern_values.stderr is what povray 3.7.0 printed for this file: circe's output must be
// exactly that. gradient's vector is made unit, as POV-Ray's Parse_Pattern does.
#macro Probe(Name, F)
  #local I = 0;
  #while (I < 8)
    #if (mod(I, 4) = 0) #local S = concat(Name, ":"); #end
    #local P = <-2.3 + 0.71*I, 1.37 - 0.43*I, 0.29 + 0.53*I>;
    #local S = concat(S, " ", str(F(P.x, P.y, P.z), 0, 6));
    #if (mod(I, 4) = 3) #debug concat(S, "\n") #end
    #local I = I + 1;
  #end
#end
#declare F = function { pattern { checker } }                 Probe("checker", F) #undef F
#declare F = function { pattern { hexagon } }                 Probe("hexagon", F) #undef F
#declare F = function { pattern { brick brick_size <1, 0.5, 0.7> mortar 0.1 } } Probe("brick", F) #undef F
#declare F = function { pattern { gradient <1, 2, -0.5> } }   Probe("gradient", F) #undef F
#declare F = function { pattern { radial frequency 3 } }      Probe("radial", F) #undef F
#declare F = function { pattern { onion } }                   Probe("onion", F) #undef F
#declare F = function { pattern { leopard scale 0.3 } }       Probe("leopard", F) #undef F
#declare F = function { pattern { marble } }                  Probe("marble", F) #undef F
#declare F = function { pattern { marble turbulence 0.8 } }   Probe("marble turbulence", F) #undef F
#declare F = function { pattern { wood } }                    Probe("wood", F) #undef F
#declare F = function { pattern { wood turbulence <0.3, 0.2, 0.1> octaves 4 omega 0.6 lambda 2.5 } } Probe("wood turbulence", F) #undef F
#declare F = function { pattern { agate } }                   Probe("agate", F) #undef F
#declare F = function { pattern { agate agate_turb 0.5 } }    Probe("agate agate_turb", F) #undef F
#declare F = function { pattern { granite } }                 Probe("granite", F) #undef F
#declare F = function { pattern { bozo } }                    Probe("bozo", F) #undef F
#declare F = function { pattern { bozo turbulence 0.5 } }     Probe("bozo turbulence", F) #undef F
#declare F = function { pattern { spotted } }                 Probe("spotted", F) #undef F
#declare F = function { pattern { bumps } }                   Probe("bumps", F) #undef F
#declare F = function { pattern { dents } }                   Probe("dents", F) #undef F
#declare F = function { pattern { wrinkles } }                Probe("wrinkles", F) #undef F
#declare F = function { pattern { ripples } }                 Probe("ripples", F) #undef F
#declare F = function { pattern { ripples frequency 3 phase 0.2 } } Probe("ripples frequency phase", F) #undef F
#declare F = function { pattern { waves } }                   Probe("waves", F) #undef F
#declare F = function { pattern { crackle } }                 Probe("crackle", F) #undef F
#declare F = function { pattern { cells } }                   Probe("cells", F) #undef F
#declare F = function { pattern { spiral1 3 } }               Probe("spiral1", F) #undef F
#declare F = function { pattern { spiral2 5 } }               Probe("spiral2", F) #undef F
#declare F = function { pattern { quilted control0 0.3 control1 0.8 } } Probe("quilted", F) #undef F
#declare F = function { pattern { planar } }                  Probe("planar", F) #undef F
#declare F = function { pattern { boxed scale 3 } }           Probe("boxed", F) #undef F
#declare F = function { pattern { cylindrical scale 3 } }     Probe("cylindrical", F) #undef F
#declare F = function { pattern { spherical scale 3 } }       Probe("spherical", F) #undef F
#declare F = function { pattern { function { x*y - z } } }    Probe("function", F) #undef F
#declare F = function { pattern { gradient x sine_wave frequency 2 phase 0.1 } }    Probe("sine_wave", F) #undef F
#declare F = function { pattern { gradient x scallop_wave frequency 2 phase 0.1 } } Probe("scallop_wave", F) #undef F
#declare F = function { pattern { gradient x triangle_wave frequency 2 phase 0.1 } } Probe("triangle_wave", F) #undef F
#declare F = function { pattern { gradient x ramp_wave frequency 2 phase 0.1 } }    Probe("ramp_wave", F) #undef F
#declare F = function { pattern { onion warp { turbulence 0.4 octaves 3 } } }       Probe("warp turbulence", F) #undef F
#declare F = function { pattern { gradient x warp { repeat 0.5*y offset 0.3*x flip x } } } Probe("warp repeat", F) #undef F
#declare F = function { pattern { onion warp { black_hole <0, 0, 1>, 2.5 strength 1.5 falloff 2 } } } Probe("warp black_hole", F) #undef F
#declare F = function { pattern { bozo scale 0.5 rotate <20, 30, 40> translate <1, 2, 3> } } Probe("transforms", F) #undef F
sphere { 0, 1 pigment { rgb 1 } }
