// An array not declared mixed holds one kind of value.
#declare A = array[2];
#declare A[0] = 1;
#declare A[1] = "two";
