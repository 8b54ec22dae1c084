superellipsoid { <0, 1> }
