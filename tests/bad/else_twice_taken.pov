// A second #else of one #if, the #else branch taken.
#if (0)
  sphere { 0, 1 }
#else
  sphere { 0, 2 }
#else
  sphere { 0, 3 }
#end
