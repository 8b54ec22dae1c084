sphere { 0, 1 material { skin { thickness 2 } } }
