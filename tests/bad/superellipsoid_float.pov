superellipsoid { 1 }
