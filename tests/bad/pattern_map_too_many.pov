// A color_map holds at most 256 entries, as POV-Ray's.
sphere { 0, 1 pigment { gradient y color_map {
#for (I, 0, 256) [I / 256 rgb I / 256] #end
} } }
