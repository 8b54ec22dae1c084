// string_declare: a string's #declare may end without ';', as in POV-Ray 3.7 (which forces the
// semicolon for floats, vectors and colours only); what follows is read in its turn, a directive
// or a statement, or a macro call reading the name just declared (portfolio/c_colors.pov's
// `#declare Comment=""` then `HTMLgen(..., Comment)`), an array too (arrays.inc's Resize_Array).
// Checked against povray 3.7.0: the same output.
#macro Show(T) #debug concat("shown: ", T, "\n") #end
#macro First(A) #debug concat("first: ", A[0], "\n") #end
#declare Comment = "comment"
Show(Comment)
#declare Ar = array[1] { "a" }
#declare Copy = Ar
First(Copy)
#declare Font = "cyrvetic.ttf"
#declare Name = concat("font ", Font)
#debug concat(Name, "\n")
#declare Last = "last"
sphere { 0, 1 }
#debug concat(Last, "\n")
