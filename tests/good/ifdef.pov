// ifdef: #ifdef/#ifndef test whether a name is declared (POV-Ray 3.7's Parse_Ifdef_Param: a
// keyword never is), with #else; #undef forgets the innermost declaration (a #local first).
#declare R = 0.5;
#ifdef (R) sphere { 0, R } #else box { 0, 1 } #end
#ifndef (R) box { 0, 1 } #else sphere { x, R } #end
#ifdef (Nothing) box { 0, 1 } #end
#ifndef (Nothing) sphere { y, 0.25 } #end
#ifdef (sphere) box { 0, 1 } #end
#ifdef (image_width) sphere { z, 0.125 } #end
#include "undef_local.inc"
#ifdef (G) sphere { -x, G } #end
#undef R
#ifdef (R) box { 0, 1 } #else sphere { -y, 2 } #end
#if (0)
  #ifdef (R) #else #end #ifndef (R) #end
#end
