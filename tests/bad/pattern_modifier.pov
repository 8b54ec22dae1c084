// A pattern's body ends at its modifiers.
sphere { 0, 1 pigment { bozo sphere } }
