// a sor whose heights do not rise
sor { 5, <0, 0>, <1, 1>, <1, 0.5>, <1, 2>, <0, 3> }
