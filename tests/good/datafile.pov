// datafile: #fopen/#read/#fclose of data files in a folder beside the scene, with povray 3.7.0's
// semantics (checked against it): floats, vectors and strings separated by commas, comments
// allowed; a value that ends the file without a ',' after it closes the file and undeclares its
// name, so `#while (defined(F))` reads to the end. A ',' after the last value leaves the file
// open: the next #read meets the end, closes it and leaves its names as they were (circe warns).
// tests/lang/check_cli.sh compares the stderr with datafile.stderr.
#fopen F "data/points.txt" read
#read (F, N, R)                                  // two at once
#declare I = 0;
#while (defined(F))
  #read (F, P)
  #if (I = 2) #declare Name = P; #end            // the string
  #if (I = 3) #declare Depth = P; #end           // -4
  #if (I != 2 & I != 3) sphere { P, R } #end
  #declare I = I + 1;
#end
#if (I != 5 | N != 3 | Depth != -4) #error "the data file was not read as written" #end
#debug Name
#debug "\n"
#fopen F "data/trailing.txt" read                // a name read to its end may be opened again
#read (F, A, B)
#if (!defined(F)) #error "a ',' after the last value closed the file" #end
#declare C = 7;
#read (F, C, D)                                  // at the end: a warning; C keeps its value
#if (C != 7) #error "C was read past the end" #end
#if (defined(F)) #error "F is still declared at the end of its file" #end
#fopen G "data/trailing.txt" read
#fclose G
#fclose G                                        // not open: a warning
sphere { 0, A + B }
