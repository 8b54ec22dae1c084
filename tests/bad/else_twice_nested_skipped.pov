// A second #else of an #if nested in a skipped branch: an error there too, as it is for the outer #if.
#if (0)
  #if (1)
    sphere { 0, 1 }
  #else
    sphere { 0, 2 }
  #else
    sphere { 0, 3 }
  #end
#else
  sphere { 0, 4 }
#end
