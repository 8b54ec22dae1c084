sphere { 0, 1 material { skin { preset "skin3" } } }
