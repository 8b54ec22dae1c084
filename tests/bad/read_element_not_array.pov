// #read into an element of a name that is not an array.
#declare A = 1;
#fopen F "read_bad_vector.txt" read
#read (F, A[0])
