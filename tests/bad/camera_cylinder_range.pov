camera { cylinder 5 location <0, 0, -5> }
