// A #macro without its #end.
#macro Ball(R)
  sphere { 0, R }
#if (1)
#end
