// circe's sky image is sky_sphere { image "file" }, mapped lat-long; an image_map pigment is refused.
sky_sphere { pigment { image_map { png "sky.png" } } }
