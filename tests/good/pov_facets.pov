// POV-Ray's facets normal: the normal quantised into facets of a size, or with coords the
// point's cells pushing it; metric as crackle's; a normal from an array element.
sphere { 0, 1 pigment { rgb 1 } normal { facets } }
sphere { 0, 1 pigment { rgb 1 } normal { facets size 0.2 metric 3 } }
sphere { 0, 1 pigment { rgb 1 } normal { facets coords 0.4 scale 0.5 } }
#declare Normals = array[2] { normal { facets size 0.05 }, normal { bumps 0.3 } }
sphere { 0, 1 pigment { rgb 1 } normal { Normals[1] } }
