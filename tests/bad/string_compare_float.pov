// A string compared with a float: POV-Ray compares two strings (strcmp) or two floats.
#declare S = "abc";
#if (S = 1) #end
