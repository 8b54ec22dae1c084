// patterns.pov: a sheet of POV-Ray's patterns, one sphere each (the same file renders in POV-Ray
// 3.7: ambient_light 0, as circe has no ambient term), row by row: checker hexagon brick gradient
// radial onion / leopard marble wood agate granite bozo / spotted bumps dents wrinkles ripples
// waves / crackle cells spiral1 spiral2 quilted planar / boxed cylindrical spherical, a
// pigment_map, warps (black_hole, turbulence), a sine_wave.
// render: -W 144 -H 120 --spp 8 --seed 1
// compare: --fail 0.05 --fail-percent 1
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 }
camera { location <0, 0, -12> look_at <0, 0, 0> angle 30 }
light_source { <-6, 8, -10> color rgb 1.1 }
light_source { <6, 2, -10> color rgb 0.4 shadowless }
sky_sphere { pigment { color rgb 0.05 } intensity 1 }
sphere { 0, 0.45 pigment { checker rgb <1,0.9,0.2>, rgb <0.1,0.2,0.6> scale 0.3 } translate <-2.5, 2, 0> } // checker
sphere { 0, 0.45 pigment { hexagon rgb <0.9,0.1,0.1>, rgb <0.1,0.7,0.1>, rgb <0.1,0.1,0.8> scale 0.12 rotate x*90 } translate <-1.5, 2, 0> } // hexagon
sphere { 0, 0.45 pigment { brick rgb 0.8, rgb <0.6,0.15,0.1> scale 0.03 } translate <-0.5, 2, 0> } // brick
sphere { 0, 0.45 pigment { gradient x color_map { [0 rgb <0,0,0.6>] [1 rgb <1,0.8,0.3>] } scale 0.5 } translate <0.5, 2, 0> } // gradient
sphere { 0, 0.45 pigment { radial frequency 6 rotate x*90 } translate <1.5, 2, 0> } // radial
sphere { 0, 0.45 pigment { onion scale 0.1 color_map { [0 rgb 0.1] [1 rgb <0.9,0.5,0.1>] } } translate <2.5, 2, 0> } // onion
sphere { 0, 0.45 pigment { leopard scale 0.06 color_map { [0 rgb 0.9] [1 rgb <0.3,0.15,0>] } } translate <-2.5, 1, 0> } // leopard
sphere { 0, 0.45 pigment { marble turbulence 0.8 scale 0.4 } translate <-1.5, 1, 0> } // marble
sphere { 0, 0.45 pigment { wood turbulence 0.05 scale 0.08 rotate x*90 } translate <-0.5, 1, 0> } // wood
sphere { 0, 0.45 pigment { agate scale 0.4 } translate <0.5, 1, 0> } // agate
sphere { 0, 0.45 pigment { granite scale 0.5 } translate <1.5, 1, 0> } // granite
sphere { 0, 0.45 pigment { bozo scale 0.15 } translate <2.5, 1, 0> } // bozo
sphere { 0, 0.45 pigment { spotted scale 0.15 } translate <-2.5, 0, 0> } // spotted
sphere { 0, 0.45 pigment { bumps scale 0.1 color_map { [0 rgb <0,0,0.3>] [1 rgb <0.9,0.9,1>] } } translate <-1.5, 0, 0> } // bumps
sphere { 0, 0.45 pigment { dents scale 0.15 color_map { [0 rgb 1] [1 rgb <0.4,0,0>] } } translate <-0.5, 0, 0> } // dents
sphere { 0, 0.45 pigment { wrinkles scale 0.2 } translate <0.5, 0, 0> } // wrinkles
sphere { 0, 0.45 pigment { ripples frequency 20 color_map { [0 rgb <0,0.2,0.5>] [1 rgb <0.7,0.9,1>] } } translate <1.5, 0, 0> } // ripples
sphere { 0, 0.45 pigment { waves frequency 8 color_map { [0 rgb <0,0.2,0.5>] [1 rgb <0.7,0.9,1>] } } translate <2.5, 0, 0> } // waves
sphere { 0, 0.45 pigment { crackle scale 0.15 color_map { [0 rgb 0] [0.05 rgb 0] [0.12 rgb 0.9] [1 rgb 0.9] } } translate <-2.5, -1, 0> } // crackle
sphere { 0, 0.45 pigment { cells scale 0.15 color_map { [0 rgb <1,0,0>] [0.5 rgb <0,1,0>] [1 rgb <0,0,1>] } } translate <-1.5, -1, 0> } // cells
sphere { 0, 0.45 pigment { spiral1 3 scale 0.3 color_map { [0 rgb 1] [1 rgb <0.8,0,0.3>] } } translate <-0.5, -1, 0> } // spiral1
sphere { 0, 0.45 pigment { spiral2 3 scale 0.3 color_map { [0 rgb 1] [1 rgb <0,0.4,0.8>] } } translate <0.5, -1, 0> } // spiral2
sphere { 0, 0.45 pigment { quilted control0 0 control1 1 scale 0.2 color_map { [0 rgb 0.1] [1 rgb <1,0.9,0.6>] } } translate <1.5, -1, 0> } // quilted
sphere { 0, 0.45 pigment { planar scale 0.4 color_map { [0 rgb 0] [1 rgb <1,1,0.5>] } } translate <2.5, -1, 0> } // planar
sphere { 0, 0.45 pigment { boxed scale 0.6 color_map { [0 rgb 0] [1 rgb <0.5,1,0.5>] } } translate <-2.5, -2, 0> } // boxed
sphere { 0, 0.45 pigment { cylindrical scale 0.6 rotate x*90 color_map { [0 rgb 0] [1 rgb <1,0.5,0.5>] } } translate <-1.5, -2, 0> } // cylindrical
sphere { 0, 0.45 pigment { spherical scale 0.6 color_map { [0 rgb 0] [1 rgb <0.5,0.5,1>] } } translate <-0.5, -2, 0> } // spherical
sphere { 0, 0.45 pigment { gradient y scale 0.9 translate -0.45*y pigment_map { [0 checker rgb 1, rgb 0 scale 0.1] [1 bozo scale 0.1] } } translate <0.5, -2, 0> } // pigment_map
sphere { 0, 0.45 pigment { checker rgb 1, rgb <0.8,0,0> scale 0.15 warp { black_hole <0,0,-0.45>, 0.4 strength 1.5 } warp { turbulence 0.2 } } translate <1.5, -2, 0> } // warps
sphere { 0, 0.45 pigment { gradient x frequency 3 sine_wave color_map { [0 rgb <0.1,0.3,0>] [1 rgb <0.9,1,0.6>] } } translate <2.5, -2, 0> } // waveforms
