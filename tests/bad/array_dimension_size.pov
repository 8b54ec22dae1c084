#declare A = array[2][2];
#declare N = dimension_size(A, 3);
