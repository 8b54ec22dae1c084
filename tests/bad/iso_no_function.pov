isosurface { contained_by { box { -1, 1 } } threshold 0.5 }
