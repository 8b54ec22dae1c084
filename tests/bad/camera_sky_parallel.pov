camera { location <0, 0, -5> look_at <0, 0, 0> sky <0, 0, 1> right <0, 0, 2> }
