#declare I = 0;
#while (1)
  #declare I = I + 1;
#end
