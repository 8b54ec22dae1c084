#declare A = array[2] { 1, 2 }
#declare B = A[0][1];
