// One iteration more than the limit of 1,000,000 (tests/good/while_limit.pov runs exactly it).
#declare I = 0;
#while (I < 1000001)
  #declare I = I + 1;
#end
sphere { 0, 1 }
