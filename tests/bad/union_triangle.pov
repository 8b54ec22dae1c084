// A triangle outside a mesh, in a union (teapot3.pov, lamppost.pov): named, never "expected ...".
union { sphere { 0, 1 } triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } }
