sphere { 0, 1 texture { finish { specular -1 } } }
