// an image_map's map_type is 0 to 7 (POV-Ray: 1 spherical, 2 cylindrical, 5 torus, others planar)
sphere { 0, 1 pigment { image_map { png "none.png" map_type 9 } } }
