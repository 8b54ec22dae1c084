sphere { 0, 1 material { wax { ior -1.2 } } }
