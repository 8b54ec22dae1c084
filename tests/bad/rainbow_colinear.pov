// POV-Ray: "Rainbow's up and direction vector are co-linear."
rainbow { direction <0, 2, 0> }
