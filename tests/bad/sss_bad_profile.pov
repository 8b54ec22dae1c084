sphere { 0, 1 material { skin { profile cubic } } }
