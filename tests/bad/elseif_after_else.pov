// #elseif after the #else of its #if, in the #else that runs.
#if (0)
#else
  sphere { 0, 1 }
#elseif (1)
#end
