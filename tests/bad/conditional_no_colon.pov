// The ?: conditional needs its ":".
#declare A = (1 ? 2 3);
