// A #switch goes straight on to its first #case or #range.
#switch (1)
  sphere { 0, 1 }
  #case (1)
#end
