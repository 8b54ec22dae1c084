// POV-Ray's object pattern (entry 0 outside the object, 1 inside) and inside(object, point), both
// the inside of the object's tessellated solid (CSG by its tree). The #debug lines
// (object_pattern.stderr) are POV-Ray 3.7.0's.
camera { location <0, 0, -4> look_at 0 }
#declare Cut = difference { box { -1, 1 } sphere { <0, 0, -1>, 0.6 } rotate 10*y }
#declare Ring = torus { 1, 0.25 rotate 90*x translate <0, 0, 0.5> }
#declare Both = union { object { Cut } object { Ring } }
#macro Show(Name, O, P)
  #debug concat(Name, " at ", vstr(3, P, ", ", 0, 2), ": ", str(inside(O, P), 0, 0), "\n")
#end
Show("Cut", Cut, <0, 0, 0>)
Show("Cut", Cut, <0, 0, -0.8>)
Show("Cut", Cut, <0.9, 0.9, -0.9>)
Show("Ring", Ring, <1, 0, 0.5>)
Show("Ring", Ring, <0, 0, 0.5>)
Show("Both", Both, <0, 1, 0.5>)
Show("Both", Both, <0, 1.5, 0.5>)
Show("Both", Both, <0, 0, -0.8>)
Show("inline", sphere { <1, 2, 3>, 0.5 }, <1, 2.4, 3>)
plane { z, 0
  pigment { object { Both color rgb <1, 1, 0> color rgb <0, 0, 1> } scale 1.5 }
  finish { ambient 1 diffuse 0 }
}
box { -0.5, 0.5 translate <3, 0, 0>
  pigment { object { sphere { 0, 0.6 } pigment { checker color rgb 1 color rgb 0 scale 0.1 } pigment { rgb <1, 0, 0> } } }
}
