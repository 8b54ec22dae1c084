// environment.pov: a lat-long sky_sphere light (importance-sampled) on glossy and diffuse spheres,
// with the environment rotated.
// render: -W 64 -H 48 --spp 16 --seed 2
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 1, -5> look_at <0, 0.8, 0> angle 50 }
sky_sphere { image "../../scenes/assets/studio/studio.exr" intensity 1 rotate <0, 40, 0> }
sphere { <-1.1, 0.8, 0>, 0.8 material { diffuse { color rgb 0.8 } } }
sphere { <1.1, 0.8, 0>, 0.8
         texture { pigment { color rgb <0.8, 0.2, 0.2> } finish { diffuse 0.6 specular 0.8 roughness 0.01 } } }
plane { y, 0 material { diffuse { color rgb 0.5 } } }
