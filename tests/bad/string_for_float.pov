sphere { 0, "one" }
