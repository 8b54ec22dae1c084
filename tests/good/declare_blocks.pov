// declare_blocks: #declare of every block kind circe holds, each used where POV-Ray lets it
// stand, modified after use. declare_blocks_literal.pov writes the same scene without names.
#declare P = pigment { rgb <1, 0.5, 0.25> }
#declare P2 = pigment { P scale 2 }                 // a colour has no pattern to move
#declare F = finish { diffuse 0.8 specular 0.2 }
#declare I = interior { ior 1.33 }
#declare T = texture { pigment { P } finish { F roughness 0.3 } }
#declare M = material { texture { T } interior { I } }
#declare Cam = camera { location <0, 1, -5> look_at 0 angle 40 }
#declare L = light_source { <0, 10, 0>, 1 translate x }   // a float colour is grey
#declare Tr = transform { rotate y * 90 translate <1, 2, 3> }
#declare TrInv = transform { Tr inverse }
#declare Ball = sphere { 0, 1 }
#declare Crate = box { -1, 1 texture { T scale 2 } }
#declare Ground = plane { y, 0 }
#declare Tri = mesh { triangle { 0, x, y } }
#declare Group = union { object { Ball } object { Crate translate x * 3 } }
camera { Cam angle 50 }
light_source { L color rgb <1, 1, 0.5> }
light_source { L translate y spotlight point_at 0 }
sphere { 0, 2 pigment { P2 } finish { F } }
object { Ball transform Tr texture { T } }
object { Crate transform { Tr } transform { TrInv } }
object { Ground pigment { P } }
object { Tri material { M } scale 2 }
object { Group translate -z transform Tr }
box { 0, 1 texture { T finish { diffuse 0.5 } } interior { I } }
#declare Quad = mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }
#declare Cage = subdivision_surface { vertex_vectors { 4, 0, x, x + y, y } faces { 1, <0, 1, 2, 3> } level 1 }
#declare Moved = object { Quad translate z material { M scale 2 } }
object { Moved rotate x * 90 }
object { Cage pigment { P } }
#declare Spot = light_source { 0, rgb 2 spotlight radius 10 falloff 20 point_at y }
light_source { Spot translate -y }
#declare P3 = P;                                    // a block value copies as any value
sphere { 0, 1 pigment { P3 } }
