// string_declare: a string's #declare may end without ';', as in POV-Ray 3.7 (which forces the
// semicolon for floats, vectors and colours only); what follows is read in its turn, a directive
// or a statement. Checked against povray 3.7.0: the same output.
#declare Font = "cyrvetic.ttf"
#declare Name = concat("font ", Font)
#debug concat(Name, "\n")
#declare Last = "last"
sphere { 0, 1 }
#debug concat(Last, "\n")
