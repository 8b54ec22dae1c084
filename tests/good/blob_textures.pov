// A blob's component textures (POV-Ray's Parse_Blob_Element_Mods): each distinct one a part (a
// declared texture given twice is one part); the components without one take the object's (part 0).
#declare T = texture { pigment { rgb <0, 0, 1> } }
#declare B = blob { threshold 0.6
  sphere { 0, 1, 1 }
  sphere { x, 1, 1 pigment { rgb <1, 0, 0> } }
  cylinder { -z, z, 0.3, -1 translate 0.5*x pigment { rgb 0 } }
  sphere { -x, 1, 1 texture { T } }
  sphere { y, 1, 1 texture { T } }
}
object { B pigment { rgb 1 } }
