blob { threshold 0.5 sphere { 0, 1, 1 no_shadow } }
