#declare A = log(0);
