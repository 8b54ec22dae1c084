#include "abc
sphere { 0, 1 }
