// #for needs a name for its variable.
#for (1, 1, 3) #end
