// An image_map that names a file that is no image (a scene file).
sphere { 0, 1 texture { pigment { image_map { png "image_not_an_image.pov" } } } }
