#macro Ball(R, optional C)
  sphere { 0, R }
#end
Ball(1, 2, 3)
