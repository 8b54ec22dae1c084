// #debug takes a string.
#debug 1
