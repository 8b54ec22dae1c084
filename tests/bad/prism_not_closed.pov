// a quadratic prism whose outline does not close: POV-Ray ignores it, circe refuses it
prism { quadratic_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 2> }
