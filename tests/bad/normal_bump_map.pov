// bump_map (an image as a normal) is not there.
sphere { 0, 1 normal { bump_map { png "b.png" } } }
