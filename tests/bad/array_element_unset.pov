#declare A = array[3];
#declare A[0] = 1;
#declare B = A[2];
