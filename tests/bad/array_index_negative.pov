#declare A = array[2][3];
#declare A[1][-1] = 0;
