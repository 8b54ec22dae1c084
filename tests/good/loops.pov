// loops: #while with nested #if/#else, generating objects; a loop inside a union.
#declare I = 0;
#while (I < 4)
  #if (mod(I, 2) = 0)
    sphere { <I, 0, 0>, 0.25 }
  #else
    box { <I, 0, 0>, <I + 0.5, 0.5, 0.5> }
  #end
  #declare I = I + 1;
#end
union {
  #declare J = 0;
  #while (J < 3)
    sphere { <0, J, 0>, 0.1 }
    #declare J = J + 1;
  #end
  translate <0, 0, 5>
}
#if (0)
  #while (1) this text is skipped, even #if (1) nested #end #end
#end
