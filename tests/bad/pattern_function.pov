// A user function as a pattern waits for circe's functions.
sphere { 0, 1 pigment { function { x } } }
