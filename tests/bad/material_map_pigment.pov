// material_map picks textures: a texture's only
sphere { 0, 1 pigment { material_map { png "t.png" } } }
