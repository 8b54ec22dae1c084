// A data file that does not exist.
#fopen F "no_such_data.txt" read
