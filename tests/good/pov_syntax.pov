// pov_syntax: POV-Ray 3.7 habits of the sample scenes and standard includes, each checked against
// povray 3.7.0, which prints the same #debug lines: strings compared by strcmp, the ?:
// conditional, POV-Ray's truth within 1e-10 and its '&' and '|' at one level, commas left out
// (Parse_Comma), a float that ends before a '<' (Parse_Float reads no comparison), arrays of
// arrays and of blocks, #read into array elements, object { } of an object or a macro's, a block
// as a macro's argument, #declare of a name a #local hides, a declared sky_sphere, #version read
// and set, and the object modifiers circe records (hollow) or accepts with a warning.
#version 3.7;
#debug concat(str(strcmp("abc", "abd"), 0, 0), " ", str(("abc" = "abc"), 0, 0), str(("a" < "b"), 0, 0),
  str(("b" <= "a"), 0, 0), str(("b" > "a"), 0, 0), str(("a" >= "a"), 0, 0), str(("a" != "a"), 0, 0), "\n")
#declare S = "circe";
#if (S = "circe") #debug "a string equals\n" #end
#declare H = (1 < 0 ? 3 : 4);
#declare Third = 0.1 + 0.2;
#debug concat(str(H, 0, 0), " ", str((Third = 0.3), 0, 0), str((1 | 0 & 0), 0, 0), str(!0.00000000001, 0, 0), "\n")
#declare V = < -1 0 2 >;
#debug concat(vstr(3, V, ",", 0, 0), "\n")
#macro Add(A B) (A + B) #end
#for (I 0 2) #debug str(Add(I 10), 0, 0) #end
#debug "\n"
#declare Pts = array[4] { <1, 2>, <3, 4>
  <5, 6> <7, 8> }
#declare Names = array[3] { "a" "b", "c" }
#debug concat(vstr(2, Pts[3], ",", 0, 0), " ", Names[1], "\n")
#declare Grid = array[2] { array[2] { 1, 2 }, array[3] { 3, 4, 5 } }
#declare Grid[0][1] = 20;
#declare Copy = Grid[1];
#declare Copy[0] = 30;
#debug concat(str(Grid[0][1], 0, 0), " ", str(Grid[1][0], 0, 0), " ", str(dimension_size(Grid[1], 1), 0, 0),
  " ", str(dimension_size(Copy, 1), 0, 0), "\n")
#fopen F "data/triple.txt" read
#declare Got = array[2] { 0, 0 }                 // povray 3.7.0 reads into elements already set
#read (F, Got[0], Got[1], Vec)
#debug concat(str(Got[0] + Got[1], 0, 0), " ", vstr(3, Vec, ",", 0, 0), "\n")
#declare X = 1;                                  // #declare of a visible #local assigns the local
#macro Scoped() #local X = 2; #declare X = 3; #debug concat(str(X, 0, 0), " ") #end
Scoped()
#debug concat(str(X, 0, 0), "\n")
#version 3.5;
#declare Was = version;
#version 3.7;
#debug concat(str(Was, 0, 1), " ", str(version, 0, 1), "\n")

sphere { 0 1 }                                   // no comma after the centre
mesh2 { vertex_vectors { 3 <0, 0, 0> <1, 0, 0> <0, 1, 0> } uv_vectors { 3 <0, 0> <1, 0>
  <0, 1> } face_indices { 1 <0, 1, 2> } }
#declare Skins = array[2] { texture { pigment { rgb 0.5 } }, texture { pigment { rgb <1, 0, 0> } } }
#declare Balls = array[2] { sphere { x, 0.5 }, sphere { y, 0.5 } }
sphere { z, 1 texture { Skins[1] } }
object { Balls[1] translate z }
object { sphere { 0, 2 } translate -x }          // an object itself in object { }
#macro Ball(R) sphere { 0, R } #end
object { Ball(3) }
#macro Painted(P, R) sphere { 0, R pigment { P } } #end
Painted(pigment { rgb <0, 1, 0> }, 4)
#declare Sky = sky_sphere { pigment { rgb <0.1, 0.2, 0.3> } }
sky_sphere { Sky }
union {
  sphere { 0, 1 hollow off }
  sphere { x, 1 no_image }
  hollow no_reflection 1 double_illuminate photons { target reflection on } radiosity { importance 0.5 }
  split_union off
}
sphere { 0, 5 color rgb 1 hollow on no_image 0 }
