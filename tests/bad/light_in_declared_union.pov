// a light in a declared union: circe places the lights of CSG only where the object is placed
#declare Lamp = union { light_source { <0, 5, 0> color 1 } sphere { 0, 1 } }
object { Lamp translate x }
