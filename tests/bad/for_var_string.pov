// The loop variable of #for must stay a float.
#for (I, 1, 3)
  #declare I = "three";
#end
