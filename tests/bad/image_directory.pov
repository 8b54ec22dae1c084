// An image_map that names a folder.
sphere { 0, 1 texture { pigment { image_map { png "a_folder" } } } }
