isosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }
