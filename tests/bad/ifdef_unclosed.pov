// An #ifdef must be closed in its file.
#ifdef (Nothing)
sphere { 0, 1 }
