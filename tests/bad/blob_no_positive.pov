// only negative components: the field never reaches the threshold
blob { threshold 0.5 sphere { <0, 0, 0>, 1, -1 } cylinder { <0, 0, 0>, <1, 0, 0>, 0.5, -2 } }
