// POV-Ray's mandel and julia of exponent 2 to 33 (mandel3/4/x, julia3/4/x of pattern.cpp) seen
// through pattern functions at twelve points each. fractal_exponent.stderr is POV-Ray 3.7.0's
// output.
#macro Probe(Name, F)
  #local I = 0;
  #while (I < 12)
    #local P = <-1.4 + 0.23*I, -0.9 + 0.17*I, 0>;
    #debug concat(Name, ": ", str(F(P.x, P.y, P.z), 0, 5), "\n")
    #local I = I + 1;
  #end
#end
#declare F = function { pattern { mandel 60 } }
Probe("mandel 2", F)
#undef F
#declare F = function { pattern { mandel 60 exponent 3 } }
Probe("mandel 3", F)
#undef F
#declare F = function { pattern { mandel 60 exponent 4 } }
Probe("mandel 4", F)
#undef F
#declare F = function { pattern { mandel 60 exponent 5 } }
Probe("mandel 5", F)
#undef F
#declare F = function { pattern { mandel 60 exponent 7 } }
Probe("mandel 7", F)
#undef F
#declare F = function { pattern { julia <0.3, 0.5>, 60 exponent 3 } }
Probe("julia 3", F)
#undef F
#declare F = function { pattern { julia <-0.2, 0.6>, 60 exponent 6 } }
Probe("julia 6", F)
#undef F
#declare F = function { pattern { mandel 60 exponent 4 interior 1, 1 } }
Probe("mandel 4 interior", F)
sphere { 0, 1 }
