sphere { 0, 1 texture { finish { phong 0.5 } } }
