// #ifdef takes a name in parentheses, not an expression.
#ifdef (1 + 2) #end
