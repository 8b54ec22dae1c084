// slope_map and normal_map are not there.
sphere { 0, 1 normal { gradient x slope_map { [0 <0, 1>] [1 <1, 0>] } } }
