// A #for must be closed in its file.
#for (I, 1, 3)
sphere { 0, I }
