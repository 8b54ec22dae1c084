// A declared finish where a pigment stands is named as what it is.
#declare F = finish { diffuse 0.5 }
sphere { 0, 1 pigment { F } }
