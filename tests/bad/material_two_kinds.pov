sphere { 0, 1 material { diffuse { rgb 1 } skin { } } }
