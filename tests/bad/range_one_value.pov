// #range takes two values.
#switch (2) #range (1) #end
