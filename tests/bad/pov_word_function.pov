// A POV-Ray 3.7 reserved word circe lacks is named, never "undeclared identifier".
#declare N = 2;
#declare A = int(N / 3);
