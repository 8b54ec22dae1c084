// a sky_sphere's image_map is loaded as any image_map: a file that is not there is an error at its name.
sky_sphere { pigment { image_map { png "no_such_sky.png" map_type 1 } } }
