#declare A = log(-1);
