#declare A = 1;
#switch (A)
#end
