// #elseif is not supported: refused even in a skipped branch, where it would pick the branch.
#if (0)
  sphere { 0, 1 }
#elseif (1)
  sphere { 0, 2 }
#end
