// metallic.pov (bench/pov_side.sh): metallic highlights tinted by the pigment (gold, copper) beside a
// plain one, and a metallic reflection.
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
background { color rgb <0.4, 0.5, 0.7> }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } }
sphere { <-2.2, 1, 0>, 1 pigment { color rgb <0.9, 0.7, 0.2> } finish { diffuse 0.4 specular 0.9 roughness 0.03 metallic } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.5, 0.3> } finish { diffuse 0.3 phong 1 phong_size 30 metallic reflection { 0.4 metallic } } }
sphere { <2.2, 1, 0>, 1 pigment { color rgb <0.9, 0.7, 0.2> } finish { diffuse 0.4 specular 0.9 roughness 0.03 } }
