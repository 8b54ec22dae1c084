sphere { 0, Radius }
