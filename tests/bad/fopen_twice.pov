// A data file name still open cannot be opened again.
#fopen F "read_past_end.txt" read
#fopen F "read_past_end.txt" read
