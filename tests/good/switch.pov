// switch: #switch/#case/#range/#break/#else/#end as POV-Ray 3.7 runs them (checked against povray
// 3.7.0 with #debug of the same scene, which printed "a,bc,c,ef,d,f, N=3 J=2"): the first case that
// matches runs on through later cases and the #else until #break; #break inside an #if leaves the
// #switch; #break also leaves #while and #for. A sphere at x = 1..6 stands for a..f, y for I.
#for (I, 0, 5)
  #switch (I)
    #case (0)
      sphere { <1, I, 0>, 0.1 }
      #break
    #case (1)
      sphere { <2, I, 0>, 0.1 }
    #case (2)
      sphere { <3, I, 0>, 0.1 }
      #break
    #range (3, 4)
      #if (I = 4)
        sphere { <4, I, 0>, 0.1 }
        #break
      #end
      sphere { <5, I, 0>, 0.1 }
    #else
      sphere { <6, I, 0>, 0.1 }
  #end
#end
#switch (7) #case (1) box { 0, 1 } #end
#declare N = 0;
#while (1) #declare N = N + 1; #if (N = 3) #break #end #end
#for (J, 1, 10) #if (J = 2) #break #end #end
sphere { <N, J, 0>, 1 }
#if (0) #switch (1) #case (1) #else #break #end #end
