// warp { repeat } needs a vector along one axis.
sphere { 0, 1 pigment { checker warp { repeat <1, 1, 0> } } }
