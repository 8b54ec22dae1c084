height_field { tga "plasma.tga" }
