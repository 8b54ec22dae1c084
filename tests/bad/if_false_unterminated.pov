#if (0)
sphere { 0, 1 }
