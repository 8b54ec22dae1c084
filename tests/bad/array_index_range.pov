// An index past the end of an array: its range is named.
#declare A = array[4] { 1, 2, 3, 4 }
#declare B = A[5];
