height_field { png "no_such_height.png" smooth }
