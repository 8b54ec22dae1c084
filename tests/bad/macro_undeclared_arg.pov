#macro Ball(R)
  sphere { 0, R }
#end
Ball(Radius)
