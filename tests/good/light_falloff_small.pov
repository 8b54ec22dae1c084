// A spotlight and a cylinder whose falloff is below their radius: POV-Ray accepts both (its
// spot is then lit inside the radius only, its cylinder out to the falloff only).
light_source { <0, 5, 0> color rgb 1 spotlight radius 40 falloff 20 point_at 0 }
light_source { <0, 5, 0> color rgb 1 cylinder point_at 0 radius 2 falloff 1 }
