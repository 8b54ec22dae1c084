sphere { 0, sqrt(-4) }
