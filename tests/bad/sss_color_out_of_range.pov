sphere { 0, 1 material { wax { color rgb <1.5, 0.5, 0.5> } } }
