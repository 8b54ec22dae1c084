// user_functions_ext: what circe's functions add to POV-Ray 3.7's: the '? :' operator, '!' (POV-Ray's
// function parser refuses both), div, a declared vector's member as a constant; u and v as x and y
// in a function without parameters.
#declare H = function(q) { q < 0 ? -q : q*2 }
#debug concat(str(H(-3), 0, 0), " ", str(H(3), 0, 0), "\n")
#declare N = function(q) { !q + !!q*10 + div(7, 2)*100 + (q ? 1 : 2 ? 3 : 4)*1000 }
#debug concat(str(N(0), 0, 0), " ", str(N(5), 0, 0), "\n")
#declare D = function { u*10 + v }
#debug concat(str(D(1, 2, 3), 0, 0), "\n")
#declare V = <1, 2, 3>;
#declare Vf = function { V.y*x + V.z }
#debug concat(str(Vf(3, 0, 0), 0, 0), "\n")
