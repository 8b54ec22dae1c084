// A POV-Ray 3.7 reserved word circe lacks is named, never "undeclared identifier": a function
// of POV-Ray's user functions only (sum), written in an expression.
#declare N = 2;
#declare A = sum(N, <0, 0, 0>);
