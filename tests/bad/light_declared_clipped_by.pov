// a declared object holding a light in a clipped_by: POV-Ray refuses it too ("Illegal texture
// or patch in clip, bound or object pattern")
#declare Lamp = union { light_source { <0, 5, 0> color 1 } sphere { 0, 3 } }
sphere { 0, 1 clipped_by { object { Lamp } } }
