// A #read after the last value of a data file: its name was closed at that value.
#fopen F "read_past_end.txt" read
#read (F, A, B)
#read (F, C)
