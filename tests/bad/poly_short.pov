cubic { <1, 2, 3> }
