// An #include of a folder: not "out of memory".
#include "a_folder"
