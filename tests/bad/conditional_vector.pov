// The condition of ?: must be a float.
#declare A = (<1, 2> ? 2 : 3);
