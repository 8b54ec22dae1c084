// An #else at the level of a false #while's body: refused as it is when the loop runs.
#while (0)
  sphere { 0, 1 }
#else
#end
