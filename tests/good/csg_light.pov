// POV-Ray's light_source inside CSG: it moves with the block's transforms (and an object { }'s
// around it), every enclosing block's in turn (drums.pov, iortest.pov). <1, 0, 0> translated 5z
// and turned 90 degrees about y is <5, 0, -1>; <0, 1, 0> moved by z, then 5z, then turned: <6, 1, 0>.
// A union of lights alone is a union; in a difference a light is no operand. An interior on an
// object without a texture takes the #default texture's (iortest's Hummers).
union {
  light_source { <1, 0, 0> color 1 }
  union { light_source { <0, 1, 0> color 1 } translate z }
  sphere { 0, 0.1 }
  translate <0, 0, 5>
  rotate 90*y
}
object { union { light_source { <2, 0, 0> color 0.5 } } translate 3*y }
difference { box { -1, 1 } light_source { <0, 0, 0> color 0.2 } sphere { 0, 0.5 } scale 2 }
#default { texture { pigment { rgb 0.5 } } }
sphere { 0, 1 interior { ior 1.5 } }
