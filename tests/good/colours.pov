// colours: POV-Ray 3.7's colours are 5-vectors (red, green, blue, filter, transmit), printed with
// #debug (colours.stderr). Checked against povray 3.7.0: the same lines.
#macro P(Name, C) #debug concat(Name, " <", vstr(5, C, ", ", 0, 3), ">\n") #end
#declare C1 = rgb <0.2, 0.4, 0.6>;       P("rgb", C1)
#declare C2 = rgb 0.5;                   P("rgb float", C2)
#declare C3 = rgbf <0.1, 0.2, 0.3, 0.4>; P("rgbf", C3)
#declare C4 = rgbt <0.1, 0.2, 0.3, 0.4>; P("rgbt", C4)
#declare C5 = rgbft <1, 2, 3, 4, 5>;     P("rgbft", C5)
#declare C6 = rgbf 0.25;                 P("rgbf float", C6)
#declare C7 = color red 1 green 0.5 filter 0.25 transmit 0.125; P("named", C7)
#declare C8 = colour rgb <1, 1, 0> blue 0.75; P("rgb then blue", C8)
#declare C9 = color C1 filter 0.5;       P("colour then filter", C9)
#declare C10 = color <0.3, 0.2, 0.1, 0.9>; P("colour 4-vector", C10)
// arithmetic: a colour is a 5-vector; a float is copied into all five, a vector padded.
#declare C13 = C3 * 2;                   P("colour * 2", C13)
#declare C14 = C3 + <1, 1, 1>;           P("colour + 3-vector", C14)
#declare C15 = C1 * C3;                  P("colour * colour", C15)
#declare C16 = 0.5 * C7 + C1 / 2;        P("mix", C16)
#declare C17 = -C1;                      P("negated", C17)
// members
#debug concat(str(C7.red, 0, 3), " ", str(C7.green, 0, 3), " ", str(C7.blue, 0, 3), " ", str(C7.filter, 0, 3), " ", str(C7.transmit, 0, 3), "\n")
#debug concat(str(C1.gray, 0, 4), " ", str(C5.x, 0, 1), " ", str(C5.t, 0, 1), " ", str((C5 * 2).transmit, 0, 1), "\n")
// srgb came with POV-Ray 3.7.1 (povray 3.7.0 lacks it): red, green and blue through the sRGB
// decoding curve of IEC 61966-2-1, filter and transmit as they are.
#declare C11 = srgb <0.5, 0.04, 1>;      P("srgb", C11)
#declare C12 = srgbt <0.5, 0.5, 0.5, 0.5>; P("srgbt", C12)
sphere { 0, 1 pigment { C1 } }
sphere { 0, 1 pigment { color red 0.5 } }
sphere { 0, 1 pigment { rgb <0.5, 0.25, 0> * 2 } }
// filter and transmit have no meaning in circe's materials yet: warned about and dropped.
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.5> } }
