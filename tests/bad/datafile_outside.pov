// A data file outside the scene's folder and the -I folders is refused, saying why.
#fopen F "../escape.txt" write
