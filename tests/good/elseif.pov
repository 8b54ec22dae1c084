// elseif: #elseif picks the first true branch of an #if (or #ifdef); after the branch that ran,
// the rest is skipped to #end. Checked against povray 3.7.0: the same scene with #debug printed
// "awbzcywdw"; here a sphere at x = 1, 2, ... stands for a, b, c, d, w, x, y, z and y for I.
#for (I, 0, 3)
  #if (I = 0) sphere { <1, I, 0>, 0.1 }
  #elseif (I = 1) sphere { <2, I, 0>, 0.1 }
  #elseif (I < 3) sphere { <3, I, 0>, 0.1 }
  #else sphere { <4, I, 0>, 0.1 }
  #end
  #ifdef (Q) sphere { <6, I, 0>, 0.1 } #elseif (I = 2) sphere { <7, I, 0>, 0.1 } #end
  #if (I = 1) #if (0) #elseif (1) sphere { <8, I, 0>, 0.1 } #else #end #elseif (1) sphere { <5, I, 0>, 0.1 } #end
#end
