merge { sphere { 0, 1 } sphere { x, 1 } material { emission rgb 1 } }
