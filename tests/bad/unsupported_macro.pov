#macro M(A)
  sphere { 0, A }
#end
