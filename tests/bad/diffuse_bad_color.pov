sphere { 0, 1 material { diffuse { "red" } } }
