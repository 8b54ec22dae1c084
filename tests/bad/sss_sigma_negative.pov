sphere { 0, 1 material { skin { sigma_a <0.1, -0.2, 0.3> } } }
