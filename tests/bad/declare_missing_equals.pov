#declare A 1;
