// pov_light_object: POV-Ray's Parse_Object takes a declared object by its bare name in a
// light's looks_like (qtvrpanorama.pov), and `object { L }` of a declared light_source places the
// light (desk.pov), its looks_like moved with it by the object's transforms.
#declare Shape = sphere { 0, 0.5 }
#declare Lamp = light_source { <0, 1, 0> color rgb 1 looks_like { Shape } }
object { Lamp translate <2, 0, 0> }
light_source { <0, 5, 0> rgb 1 looks_like { Shape } }
