// A normal needs a pattern.
sphere { 0, 1 normal { scale 2 } }
