disc { 0, y, 1, 1.5 }
