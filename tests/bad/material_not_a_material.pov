#declare A = 1;
sphere { 0, 1 material { A } }
