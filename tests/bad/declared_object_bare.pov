#declare Ball = sphere { 0, 1 }
Ball
