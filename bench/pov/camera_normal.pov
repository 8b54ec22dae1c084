// camera_normal.pov (bench/pov_side.sh): a camera normal { } of a smooth pattern (leopard: no
// noise) bending the rays as POV-Ray does, a checker plane and a ball seen through it.
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 50 normal { leopard 0.6 scale 0.08 } }
light_source { <-5, 10, -8> color 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.1 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } }
