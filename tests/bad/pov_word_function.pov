// A POV-Ray 3.7 reserved word circe lacks is named, never "undeclared identifier": a function
// that needs the scene's geometry.
#declare N = 2;
#declare A = inside(N, <0, 0, 0>);
