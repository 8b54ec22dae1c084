// Issue 15.1: the #end of the loop as the value of #declare re-entered #declare without bound.
#while (1) #declare X = #end
