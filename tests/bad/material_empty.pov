sphere { 0, 1 material { } }
