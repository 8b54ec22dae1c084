// the object pattern names an object first
plane { y, 0 pigment { object { color rgb 1 color rgb 0 } } }
