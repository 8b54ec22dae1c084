#declare A = acosh(0.5);
