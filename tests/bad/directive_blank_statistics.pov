// Issue 14.6: blanks between # and an unsupported directive name keep the name whole.
sphere { 0, 1 }
#   statistics
