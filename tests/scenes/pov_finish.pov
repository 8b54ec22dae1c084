// pov_finish.pov: POV-Ray's finishes on circe's lobes (doc/language.md, "Finishes") under POV-Ray
// lights: matte, phong, specular with metallic, reflection with falloff and with fresnel, an
// explicit ambient and an emission glowing, in a constant fog. The same file renders in POV-Ray 3.7.
// render: -W 64 -H 48 --spp 16 --seed 1
// compare: --fail 0.05 --fail-percent 1
global_settings { assumed_gamma 1 ambient_light rgb <1, 0.95, 0.9> }
camera { location <0, 3, -10> look_at <0, 0.6, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 6, -6> color rgb 0.4 }
background { color rgb <0.4, 0.5, 0.7> }
fog { distance 40 color rgb <0.6, 0.65, 0.7> }
plane { y, 0 pigment { color rgb 0.6 } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { diffuse 0.8 } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 1 phong_size 40 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <0.9, 0.7, 0.2> } finish { specular 0.9 roughness 0.02 metallic reflection { 0.3 metallic } } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb 0.2 } finish { diffuse 0.3 reflection { 0.1, 0.9 falloff 2 } } }
sphere { <-2.2, 0.5, -2.5>, 0.5 pigment { color rgb <1, 0.8, 0.3> } finish { ambient 0.8 diffuse 0.2 } }
sphere { <0, 0.5, -2.5>, 0.5 pigment { color rgb <0.3, 0.9, 0.4> } finish { emission 0.6 diffuse 0.3 } }
sphere { <2.2, 0.5, -2.5>, 0.5 pigment { color rgb <0.5, 0.5, 0.9> } finish { reflection { 0, 1 fresnel } } interior { ior 1.5 } }
