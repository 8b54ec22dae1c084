#macro Ball(C, R)
  sphere { C, R }
#end
Ball(, 1)
