#macro Ball(R)
  sphere { 0, R }
#end
#declare B = Ball;
