camera { location <0, 0, -5> look_at <0, 0, 0> up <0, 0, 1> }
