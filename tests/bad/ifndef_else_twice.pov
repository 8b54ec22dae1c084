// A second #else of an #ifndef, as of an #if.
#ifndef (Nothing) #else #else #end
