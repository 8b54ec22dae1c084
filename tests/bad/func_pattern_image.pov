// circe's language loads no images: an image_map in a function's pigment is refused.
#declare P = function { pigment { image_map { png "nothing.png" } } }
