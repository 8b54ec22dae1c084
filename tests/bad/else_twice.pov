// Issue 14.2: a second #else of one #if, the first branch taken.
#if (1)
  sphere { 0, 1 }
#else
  sphere { 0, 2 }
#else
  sphere { 0, 3 }
#end
