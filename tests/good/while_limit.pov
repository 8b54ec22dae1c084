// while_limit: a #while may run exactly 1,000,000 iterations (LANG_MAX_LOOP_ITERATIONS); one more
// is refused (tests/bad/while_limit_exceeded.pov).
#declare I = 0;
#while (I < 1000000)
  #declare I = I + 1;
#end
sphere { 0, I / 1000000 }
