// A normal takes an image as a bump_map, not an image_map.
sphere { 0, 1 normal { image_map { png "b.png" } } }
