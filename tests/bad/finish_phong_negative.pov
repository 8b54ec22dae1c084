// phong is a non-negative weight.
sphere { 0, 1 finish { phong -1 } }
