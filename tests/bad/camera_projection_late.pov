camera { location <0, 0, -5> orthographic }
