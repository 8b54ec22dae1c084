// A tab between # and the name: it is the directive #macro, here unterminated.
#	macro M()
  sphere { 0, 1 }
