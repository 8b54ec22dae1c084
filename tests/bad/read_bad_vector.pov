// An error in a data file is reported in the data file, at its line.
#fopen F "read_bad_vector.txt" read
#read (F, A, B)
