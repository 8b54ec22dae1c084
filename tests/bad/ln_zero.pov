#declare A = ln(0);
