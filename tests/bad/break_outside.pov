// #break stands in a #switch, #while or #for.
sphere { 0, 1 }
#if (1) #break #end
