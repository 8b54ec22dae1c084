// min_extent and max_extent (POV-Ray's bounding box of an object: a union joins, an intersection
// meets, a difference keeps its first operand's, a transform's box of the box, a plane the huge box)
// and looks_like (the object moved to the light, then its modifiers, no_shadow; the light's later
// transforms move it; a declared light's copies each move their own)
camera { location <0, 2, -10> look_at 0 }
#declare U = union { sphere { <0, 0, 0>, 1 } sphere { <5, 0, 0>, 2 } }
#declare I = intersection { sphere { 0, 2 } box { <1, -5, -5>, <5, 5, 5> } }
#declare D = difference { box { -1, 1 } sphere { 0, 5 } }
#declare T = torus { 2, 0.5 scale <1, 2, 1> translate <1, 1, 1> }
#declare C = cylinder { <0, 0, 0>, <0, 3, 0>, 0.5 clipped_by { plane { y, 1 } } }
#declare B = box { <0, 0, 0>, <1, 2, 3> rotate 90 * y }
#declare P = plane { y, 0 }
sphere { min_extent(U), 0.1 } sphere { max_extent(U), 0.1 }
sphere { min_extent(I), 0.1 } sphere { max_extent(I), 0.1 }
sphere { min_extent(D), 0.1 } sphere { max_extent(D), 0.1 }
sphere { min_extent(T), 0.1 } sphere { max_extent(T), 0.1 }
sphere { min_extent(C), 0.1 } sphere { max_extent(C), 0.1 }
sphere { min_extent(B), 0.1 } sphere { max_extent(B), 0.1 }
sphere { <0, min_extent(P).y / 1e10, max_extent(P).x / 1e10>, 0.1 }
#declare L = light_source { <0, 3, 0> color rgb 1 looks_like { sphere { 0, 0.2 } translate 0.5 * z } translate x }
light_source { L }
light_source { L translate -2 * x }
