// a declared unbounded quadric (shapes.inc has dozens) is fine: only its use is an error
#declare Q = quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
#declare Unused = cubic { <0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1> }
sphere { 0, 1 }
object { Q scale 2 }
