// a material_map needs its textures
sphere { 0, 1 texture { material_map { png "t.png" once } } }
