// a texture's object pattern comes first in it, as POV-Ray reads it
#declare O = sphere { 0, 1 }
sphere { 0, 1 texture { finish { ambient 0 } object { O texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }
