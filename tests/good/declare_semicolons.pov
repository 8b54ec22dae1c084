// declare_semicolons: as povray 3.7.0, only a float, vector or colour #declare needs its ';', and
// only from #version 3.5 on: a string or a block name needs none (POV-Ray's samples write
// `#declare Font = "cyrvetic.ttf"`). The token after such a value is read again after the name
// is defined: a directive there runs, in order.
#declare Font = "cyrvetic.ttf"
#declare Font2 = Font
#if (1) #declare Radius = 2; #end
#declare P = pigment { rgb <1, 0, 0> }
#declare P2 = P
sphere { 0, Radius pigment { P2 } }
#declare Name = "b"
sphere { 1, 1 }
#version 3.1;
#declare A = 3
#declare V = <1, 2, 3>
sphere { V, A }
#version 3.7;
#debug Font2
#declare Last = "at the end of the file"
