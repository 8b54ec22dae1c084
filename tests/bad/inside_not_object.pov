// inside tests an object
#declare A = 1;
#if (inside(A, <0, 0, 0>)) #end
