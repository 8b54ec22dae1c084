// #error stops the parse at the directive, with its text on one line.
sphere { 0, 1 }
#error "stopped: \"why\"\n"
sphere { 0, 2 }
