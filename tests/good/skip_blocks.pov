// skip_blocks: a skipped branch pairs every POV-Ray block directive (#if #ifdef #ifndef #while
// #for #switch #macro) with its #end, as POV-Ray does; blanks may follow '#' (POV-Ray's finish.inc
// and stones.inc write `#   declare` and `#\tifdef`).
#if (0) #macro M() #end #end
#if (0)
  #macro Ball(R)
    sphere { 0, R }
  #end
  #ifdef (Foo) #declare A = 1; #end
	#	ifndef (Foo) #declare A = 2; #end
  #for (I, 0, 3) sphere { I, 1 } #end
  #switch (A)
    #case (1) #declare B = 1; #break
    #range (2, 3) #declare B = 2; #break
    #else #declare B = 3;
  #end
  #while (1) #end
  #   debug "not run"
#else
  #   declare R = 2;
  #	local S = 3;
#end
#if (1)
  sphere { 0, R }
#else
  #macro Unused() #end
  #ifdef (R) #end
#end
#  if (S = 3) sphere { x, S } #  end
