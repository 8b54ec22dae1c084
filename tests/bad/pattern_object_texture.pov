// POV-Ray's object pattern of textures is named where it is written.
#declare O = sphere { 0, 1 }
sphere { 0, 1 texture { object { O texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }
