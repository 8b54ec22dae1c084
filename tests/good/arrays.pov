// arrays: POV-Ray 3.7's array[N]..., initialisers, elements assigned one by one, dimensions,
// dimension_size, defined() and #ifdef of an element, #declare copying an array and a macro
// argument passing it by reference; printed with #debug (arrays.stderr). Checked against
// povray 3.7.0: the same lines.
#declare A = array[4];
#ifdef (A[1]) #debug "A[1] set\n" #else #debug "A[1] unset\n" #end
#declare A[1] = 10;
#ifdef (A[1]) #debug "A[1] set\n" #else #debug "A[1] unset\n" #end
#ifndef (A[2]) #debug "A[2] unset\n" #end
#debug concat(str(defined(A[1]), 0, 0), str(defined(A[3]), 0, 0), str(defined(A), 0, 0), str(defined(Nothing), 0, 0), "\n")
#declare M = array[2][3] { {1, 2, 3}, {4, 5, 6} }
#debug concat(str(dimensions(M), 0, 0), " ", str(dimension_size(M, 1), 0, 0), "x", str(dimension_size(M, 2), 0, 0), " ", str(M[1][2], 0, 0), str(M[0][1], 0, 0), "\n")
#declare Sum = 0;
#for (I, 0, 1) #for (J, 0, 2) #declare Sum = Sum + M[I][J] * (I + 1); #end #end
#debug concat("sum ", str(Sum, 0, 0), "\n")
#declare M[0][0] = 100;
#debug concat(str(M[0][0], 0, 0), " ", str(M[1.7][0.2], 0, 0), "\n")
#declare V = array[3] { <1, 2, 3>, x, 2 * y };
#debug concat(vstr(3, V[0] + V[2], ", ", 0, 0), " ", str(V[0].z, 0, 0), "\n")
#declare S = array[2] { "one", "two" };
#debug concat(S[1], " ", S[0], "\n")
#debug S[1]
#debug "\n"
// #declare copies an array: the copy is changed, the original is not.
#declare B = M;
#declare B[1][1] = -5;
#debug concat(str(M[1][1], 0, 0), " ", str(B[1][1], 0, 0), "\n")
// a macro's array argument is passed by reference
#macro Fill(Arr, X) #for (I, 0, dimension_size(Arr, 1) - 1) #declare Arr[I] = X * I; #end #end
#declare C = array[5];
Fill(C, 3)
#debug concat(str(C[0], 0, 0), " ", str(C[4], 0, 0), "\n")
#declare Deep = array[2][2][2] { { {1, 2}, {3, 4} }, { {5, 6}, {7, 8} } };
#debug concat(str(Deep[1][0][1], 0, 0), " ", str(dimensions(Deep), 0, 0), "\n")
// 'array mixed' (POV-Ray 3.8's; povray 3.7.0 lacks it) holds values of different kinds.
#declare Mx = array mixed[2] { 1, "two" }
#debug concat(str(Mx[0], 0, 0), " ", Mx[1], "\n")
sphere { V[0], 1 }
