camera { location <0, 0, -5> look_at 0 }
#declare S = 3;
sphere { min_extent(S), 1 }
