// a lathe with cubic_spline needs at least four points (POV-Ray: "must have at least four points")
lathe { cubic_spline 3, <0, 0>, <1, 1>, <0, 2> }
