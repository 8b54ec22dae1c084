// #debug takes a string expression: a call giving a float is refused.
#debug concat(str(1, 0, 0), "\n") #debug strlen("a")
