// include_path: -I search, #local scoping in an include file, nested includes.
#declare Size = 1;
#include "shapes.inc"
sphere { 0, Size }        // Size is still 1: the include's #local Size died with it
sphere { 0, Shared }      // #declare in an include is global
