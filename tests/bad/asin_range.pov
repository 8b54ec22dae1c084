#declare A = asin(2);
