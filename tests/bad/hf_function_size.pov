// A height field function needs at least 2 x 2 points.
height_field { function 1, 100 { x } }
