// shapes.pov: one of each of POV-Ray's shapes circe tessellates (cylinder capped and open, cone to an
// apex, torus, disc with a hole, polygon with a hole, superellipsoid, ellipsoid quadric, smooth height
// field with a water level) over a plane. The same file renders in POV-Ray 3.7 (bench/README.md,
// "Shapes", has the pair).
// render: -W 80 -H 60 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <4, 9, -6>, rgb 1 }
plane { y, 0 pigment { rgb 0.6 } }
cylinder { <-3, 0, 0>, <-3, 2, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
cone { <-1.5, 0, 0>, 0.6, <-1.5, 2, 0>, 0 pigment { rgb <0.9, 0.6, 0.2> } }
torus { 0.7, 0.25 sturm rotate x * 90 translate <0.2, 1, 0> pigment { rgb <0.3, 0.8, 0.3> } }
disc { <2.2, 1, 0>, <0, 0.3, -1>, 0.8, 0.3 pigment { rgb <0.2, 0.4, 0.9> } }
polygon { 10, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <0.25, 0.25>, <0.75, 0.25>, <0.75, 0.75>, <0.25, 0.75>,
  <0.25, 0.25> rotate x * 60 translate <2.6, 0.05, -2> pigment { rgb <0.8, 0.8, 0.2> } }
superellipsoid { <0.3, 0.6> scale 0.6 translate <-2.3, 0.6, 2> pigment { rgb <0.7, 0.3, 0.8> } }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 scale <0.8, 0.4, 0.4> translate <0, 0.4, 2.2> pigment { rgb <0.3, 0.8, 0.8> } }
cylinder { <0.6, 0, -1.8>, <1.6, 0.5, -1.8>, 0.3 open pigment { rgb <0.9, 0.9, 0.9> } }
height_field { png "hf.png" smooth water_level 0.2 translate <-0.5, 0, -0.5> scale <2, 1, 2> translate <-1.5, 0, -2.3>
  pigment { rgb <0.8, 0.5, 0.4> } }
