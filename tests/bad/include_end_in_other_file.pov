#if (1)
#include "end_only.inc"
