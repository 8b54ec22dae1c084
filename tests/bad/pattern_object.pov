// POV-Ray's object pattern is named where it is written (advanced/abyss, object_pattern).
#declare O = sphere { 0, 1 }
sphere { 0, 1 pigment { object { O rgb 0, rgb 1 } } }
