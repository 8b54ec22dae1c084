// a light with looks_like in a declared union: circe would place the looks_like objects apart
// from the copies, so it refuses the light (POV-Ray copies both)
#declare Lamp = union {
  light_source { <0, 5, 0> color 1 looks_like { sphere { 0, 0.2 } } }
  sphere { 0, 1 }
}
object { Lamp translate x }
