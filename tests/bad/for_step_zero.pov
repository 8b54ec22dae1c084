// #for with a step of 0 would never end.
#for (I, 1, 10, 1 - 1)
#end
