sphere { 0, 1 material { skin { thicknes 2 } } }
