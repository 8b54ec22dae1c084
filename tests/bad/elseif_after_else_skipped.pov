// #elseif after the #else of its #if, where the first branch ran and the rest is skipped.
#if (1)
  sphere { 0, 1 }
#elseif (0)
#else
#elseif (1)
#end
