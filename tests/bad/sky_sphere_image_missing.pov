// A sky_sphere image that does not exist.
sky_sphere { image "no_such_sky.exr" }
