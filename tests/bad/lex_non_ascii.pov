sphere { 0, 1 }
Ã©
