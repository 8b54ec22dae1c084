camera { location <0, 0, -5> direction <0, 0, 1> up <0, 0, 1> }
