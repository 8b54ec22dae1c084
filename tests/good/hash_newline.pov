// POV-Ray reads a directive's name as the next token after '#': blanks, newlines and comments
// may stand between them, as they may between any two tokens.
#
declare R = 2;
# /* a comment */ if (R > 1)
  sphere { <0, 0, 0>, R }
#
  // a line comment
  end
#	while (R > 3) sphere { 0, 9 } # end
