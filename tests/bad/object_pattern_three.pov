// the object pattern takes two entries
#declare B = box { -1, 1 }
plane { y, 0 pigment { object { B color rgb 1 color rgb 0 color rgb 0.5 } } }
