// loop_memo: loop and macro bodies read many times through the parser's token memo give what
// they give read afresh: nested #while and #for, a #switch and a skipped #if branch in a loop, a
// macro defined inside a loop and called from it, a macro whose body ends a frame (its value is
// the body's last token), strings and numbers. loop_memo.stderr is what povray 3.7.0 printed.
#macro Twice(A) (2*A) #end
#declare Total = 0;
#declare I = 0;
#while (I < 4)
	#macro Add(B) #declare Total = Total + B + I; #end
	#for (J, 1, 3)
		#switch (mod(J, 3))
		#case (0) Add(Twice(J)) #break
		#case (1) #if (I = 2) Add(100) #else Add(1) #end #break
		#else #declare Total = Total - 0.5;
		#end
	#end
	#declare S = concat("turn ", str(I, 0, 0), ": ", str(Total, 0, 1), "\n");
	#debug S
	#declare I = I + 1;
#end
#declare K = 0;
#while (K < 3) #declare K = K + Twice(1) - 1; #debug concat(str(K, 0, 0), " ") #end
#debug "\n"
