// A #switch must be closed in its file.
#switch (2)
  #case (1) sphere { 0, 1 }
  #range (3, 4)
