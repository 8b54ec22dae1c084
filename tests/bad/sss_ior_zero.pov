sphere { 0, 1 material { skin { ior 0 } } }
