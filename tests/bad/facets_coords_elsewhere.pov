// coords belongs to facets
sphere { 0, 1 normal { bumps coords 0.5 } }
