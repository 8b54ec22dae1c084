// a slope_map entry is a value and <height, slope>.
sphere { 0, 1 normal { bumps slope_map { [0 <0, 1>] [1] } } }
