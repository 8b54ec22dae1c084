// for: #for (I, start, end [, step]) as POV-Ray 3.7 runs it (checked against povray 3.7.0): the end
// is included, within 1e-10; a negative step counts down; a loop that does not run still declares
// its variable with the start; the variable ends one step past the end; loops nest.
#for (I, 1, 3) sphere { <I, 0, 0>, 0.25 } #end
#for (J, 2, 0, -0.5) box { <J, 0, 0>, <J + 0.25, 1, 1> } #end
#for (K, 5, 1) sphere { 0, 9 } #end
#declare N = 0;
#for (K, 0, 0.3, 0.1) #declare N = N + 1; #end
#for (A, 1, 2) #for (B, 1, 2) sphere { <A, B, 5>, 0.1 } #end #end
#if (0) #for (Q, 1, 2) #else #end #end
sphere { <N, K, I>, 1 }
