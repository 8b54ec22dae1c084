// macro: #macro with POV-Ray 3.7's semantics. Each sphere's x is a test's number, its y the value
// found. Checked against povray 3.7.0: the same scene printing each y with #debug str() (and 13's
// max_extent) gave the same numbers, but for 7 and 8: `optional` came with POV-Ray 3.7.1 (3.7.0
// reads it as a parameter's name), so they follow 3.7.1's documentation.
#macro Show(N, V) sphere { <N, V, 0>, 0.1 } #end
// 1, 2: a bare identifier is passed by reference: #declare or #local of the parameter changes it.
#macro SetD(P) #declare P = 5; #end
#macro SetL(P) #local P = 7; #end
#declare A = 1;
SetD(A) Show(1, A)
SetL(A) Show(2, A)
// 3: anything else is passed by value: the caller's variable stays.
SetD(A + 0) Show(3, A)
// 4, 5: a macro in a value's place; a nested call as an argument.
#macro Sq(V) (V * V) #end
Show(4, Sq(3) + 1)
Show(5, Sq(Sq(2)))
// 6: #local lives in the call; #declare is global.
#macro Locals() #local Q = 3; #declare G = 4; #end
Locals()
#ifdef (Q) Show(6, 1) #else Show(6, G) #end
// 7, 8: optional parameters: omitted, the parameter is undefined.
#macro Opt(N, optional B) #ifdef (B) Show(N, B) #else Show(N, -1) #end #end
Opt(7, 2)
Opt(8)
// 9: recursion, with the accumulator by reference.
#macro Fact(N, R) #if (N > 1) #declare R = R * N; Fact(N - 1, R) #end #end
#declare F = 1;
Fact(5, F)
Show(9, F)
// 10: a recursive macro in a value's place.
#macro Sum(N) #if (N > 0) #local R = N + Sum(N - 1); #else #local R = 0; #end R #end
Show(10, Sum(4))
// 11: a macro defining a macro.
#macro Maker(K) #declare MadeK = K; #macro Made(N) Show(N, MadeK) #end #end
Maker(42)
Made(11)
// 12: a #while in the body, a parameter by reference as the counter.
#macro Count(C) #local I = 0; #while (I < 3) #declare C = C + 1; #local I = I + 1; #end #end
#declare C = 0;
Count(C)
Show(12, C)
// 13: object items: a macro inside an object block.
#macro Up(D) translate <0, D, 0> #end
sphere { <13, 0, 0>, 0.1 Up(6) }
// 14: a parameter hides a global of its name; the global is back after the call.
#declare V = 8;
#macro Hide(V) Show(14, V) #end
Hide(9)
Show(14.5, V)
// 15: a macro's name inside a skipped branch pairs its #end.
#if (0) #macro Never() #end #else Show(15, 1) #end
// 16: #declare of a parameter passed by value assigns the parameter, not a global.
#macro ByValue(P) #declare P = 5; Show(16, P) #end
ByValue(1)
#ifdef (P) Show(16.5, P) #else Show(16.5, 0) #end
// 17: a macro defined in an include file works after the file ends; the file's #local does not.
#include "macro_lib.inc"
FromInc(17)
#ifdef (Hidden) Show(17.5, 1) #else Show(17.5, 0) #end
// 18, 19: a macro as a #declare's object value (the ';' after the call), and as a material item.
#macro Ball(P) sphere { P, 0.1 } #end
#declare B = Ball(<18, 1, 0>);
object { B }
#macro Green() material { texture { pigment { rgb <0, 1, 0> } } } #end
sphere { <19, 0, 0>, 0.1 Green() }
