// trace(object, start, direction [, normal]): the first hit on the object (on its tessellated
// surface, within its distance of the exact one), the outward normal into a declared name; a miss
// gives <0, 0, 0> for both. The #debug lines (trace.stderr) are POV-Ray 3.7.0's but for the sign
// of one zero (POV-Ray: "transformed: -0.000, 5.000, ...").
camera { location <0, 0, -4> look_at 0 }
#macro Show(Name, P, N)
  #debug concat(Name, ": ", vstr(3, P, ", ", 0, 3), " normal ", vstr(3, N, ", ", 0, 3), "\n")
#end
#declare Ball = sphere { <0, 0, 0>, 1 }
#declare N = <9, 9, 9>;
#declare P = trace(Ball, <0, 0, -5>, z, N);
Show("sphere", P, N)
#declare P = trace(Ball, <0.6, 0, -5>, <0, 0, 3>, N);
Show("sphere off axis", P, N)
#declare Cut = difference { box { -1, 1 } sphere { <0, 0, -1>, 0.5 } }
#declare P = trace(Cut, <0, 0, -5>, z, N);
Show("difference, in the cut", P, N)
#declare P = trace(Cut, <0.8, 0.8, -5>, z, N);
Show("difference, on the box", P, N)
#declare Moved = object { Ball scale <2, 1, 1> rotate 90*z translate <0, 3, 0> }
#declare P = trace(Moved, <0, 10, 0>, -y, N);
Show("transformed", P, N)
#declare Floor = plane { y, -1 }
#declare P = trace(Floor, <3, 4, 5>, <1, -1, 0>, N);
Show("plane", P, N)
#declare P = trace(Cut, <0, 3, -5>, z, N);
Show("miss", P, N)
#declare Q = trace(Ball, <0, 0, -5>, z);
Show("no normal asked", Q, N)
#macro Drop(Obj, From, Norm) trace(Obj, From, -y, Norm) #end
#declare M = <0, 0, 0>;
#declare At = Drop(Cut, <0.5, 5, 0.5>, M);
Show("through a macro", At, M)
sphere { At, 0.05 }
