bounded_by { box { -1, 1 } }
