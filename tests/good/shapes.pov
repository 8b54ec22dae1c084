// POV-Ray's shapes in the IR: POV-Ray's syntax (commas optional), defaults, declarations
#declare R = 0.5;
cylinder { <1, 2, 3> <1, 4, 3> R }
cylinder { 0, x, 1 open pigment { rgb <1, 0, 0> } }
cone { <0, 0, 0>, 1, <0, 2, 0>, 0 }
cone { 0, 0.5, y, 1 open }
torus { 2, 0.5 rotate x * 90 }
disc { <0, 1, 0>, <0, 0, -2>, 1.5 }
disc { 0, y, -2, R }
disc { 0, y, 2 R }
polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }
polygon { 4, <0, 0, 1>, <1, 0, 1>, <1, 1, 1>, <0, 1, 1> }
superellipsoid { <0.25, 1> scale 2 }
height_field { "data/hf.png" water_level 0.25 }
height_field { exr "hf.exr" smooth }
quadric { <1, 2, 3>, <0, 0, 0>, <0, 0, 0>, -1 }
#declare Ell = quadric { <1, 1, 1> <0, 0, 0> <0, 0, 0>, -1 }
object { Ell scale 2 }
#declare Sq = quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> }
#declare Cyl = cylinder { -y, y, 1 }
object { Cyl translate 5 * x }
// a float as both exponents (POV-Ray promotes it: cliche.pov)
superellipsoid { 0.15 translate 4 * y }
