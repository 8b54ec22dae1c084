sphere { 0, 1 interior { ior 1.5 } }
