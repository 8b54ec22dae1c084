// #write needs a file open for writing.
#fopen F "read_past_end.txt" read
#write (F, "x")
