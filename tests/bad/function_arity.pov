#declare A = atan2(1);
