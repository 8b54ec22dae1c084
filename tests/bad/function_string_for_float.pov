// A string where a float is expected is located at the argument.
#declare A = sin("one");
