// image_map's map_type 3 (torus) and above are refused.
sphere { 0, 1 pigment { image_map { png "none.png" map_type 3 } } }
