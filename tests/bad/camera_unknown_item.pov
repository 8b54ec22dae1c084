camera { location <0, 0, -5> fov 40 }
