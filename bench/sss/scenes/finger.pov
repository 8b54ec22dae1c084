// finger.pov: a thin finger-like skin cylinder, about 15 mm across and 70 mm long with rounded
// ends: a Catmull-Clark surface (level 4) of a square prism cage of 4 segments. A strong light just
// behind it shows the light crossing it; a weak light from the camera fills the rest. Thin against
// skin's scattering radius: most circles cut the surface obliquely (the talk's weight is worst here).
#version 3.7;
global_settings { mm_per_unit 10 }
camera { location <0.5, 1.0, -7> look_at <0, 0, 0> angle 36 }
light_source { <-0.5, 1.5, 5> color rgb 1 intensity 400 }
light_source { <2, 2, -8> color rgb 1 intensity 10 }
background { color rgb 0 }
subdivision_surface {
  vertex_vectors { 20, <-3,0.9,0.9>, <-3,-0.9,0.9>, <-3,-0.9,-0.9>, <-3,0.9,-0.9>, <-1.5,0.9,0.9>, <-1.5,-0.9,0.9>, <-1.5,-0.9,-0.9>, <-1.5,0.9,-0.9>, <0,0.9,0.9>, <0,-0.9,0.9>, <0,-0.9,-0.9>, <0,0.9,-0.9>, <1.5,0.9,0.9>, <1.5,-0.9,0.9>, <1.5,-0.9,-0.9>, <1.5,0.9,-0.9>, <3,0.9,0.9>, <3,-0.9,0.9>, <3,-0.9,-0.9>, <3,0.9,-0.9> }
  faces { 18, <1,5,4,0>, <2,6,5,1>, <3,7,6,2>, <0,4,7,3>, <5,9,8,4>, <6,10,9,5>, <7,11,10,6>, <4,8,11,7>, <9,13,12,8>, <10,14,13,9>, <11,15,14,10>, <8,12,15,11>, <13,17,16,12>, <14,18,17,13>, <15,19,18,14>, <12,16,19,15>, <3,2,1,0>, <16,17,18,19> }
  level 4
  rotate <0, 0, 12>
  material { skin {} }
}
