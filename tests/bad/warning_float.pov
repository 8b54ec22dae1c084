// #warning of a name that is not a string.
#declare N = 2;
#warning N
