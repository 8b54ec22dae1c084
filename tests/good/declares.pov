// declares: every value kind, #local, every operator and function, the vector '>' rule, clock.
#declare F = 2 * (3 + 4) / 7 - -1;            // 3
#declare V = <1, 2, 3> * 2 + x;               // <3, 4, 6>
#declare C = color rgb <1, 0.5, 0.25>;
#declare C2 = rgb 0.5;
#declare S = "albedo.png";
#local L = F + 1;                             // main file: same as #declare
#declare Cmp = <1, (2 > 1), (3 >= 4)>;        // '>' inside parentheses is a comparison
#declare Logic = (1 & 0) | !0;                // 1
#declare Fns = <sin(0) + cos(0) + tan(0), asin(1) - acos(1) + atan2(1, 1), sqrt(16) + pow(2, 3)>;
#declare Fns2 = <exp(0) + log(1) + abs(-2), min(3, 1, 2) + max(1, 5) + mod(7, 3), floor(1.5) + ceil(1.5)>;
#declare Fns3 = <radians(180) - pi, degrees(pi), vlength(<3, 4, 0>)>;
#declare N = vnormalize(<0, 0, 5>);
#declare D = vdot(<1, 2, 3>, <4, 5, 6>);       // 32
#declare Cr = vcross(x, y);                   // z
#declare T = clock * 10;
#declare Cmp2 = <(1 < 2), (1 <= 1), (1 = 2)> + <(1 != 2), 0, 0>;
#declare Mat = material { diffuse { color C } }
#declare Ball = sphere { 0, 1 material { Mat } }
#declare Eq = (F = 3);
sphere { V, F material { diffuse { color C2 } } }
sphere { Cmp, Logic }
sphere { Fns, 1 }
sphere { Fns2, 1 }
sphere { Fns3, L }
sphere { N + Cr, D / 32 }
sphere { <T, Eq, 0>, 1 }
sphere { Cmp2, 1 material { diffuse { image S } } }
object { Ball translate y * 3 }
