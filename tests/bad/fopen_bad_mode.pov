// #fopen takes read, write or append.
#fopen F "read_past_end.txt" update
