// materials: every material form, every SSS parameter, every preset, both SSS forms.
sphere { 0, 1 material { diffuse { color rgb <0.8, 0.7, 0.6> } } }
sphere { 0, 1 material { diffuse { image "albedo.png" } } }
sphere { 0, 1 texture { pigment { color rgb 0.5 } finish { diffuse 0.8 specular 0.3 roughness 0.1 } } interior { ior 1.5 } }
sphere { 0, 1 texture { pigment { image_map { png "wood.png" } } } }
sphere { 0, 1 pigment { rgb <1, 1, 0> } finish { specular 0.5 } }
sphere { 0, 1 material { emission rgb <4, 4, 4> } }
sphere { 0, 1 material { diffuse { color rgb 0.2 } emission rgb 1 } }
sphere { 0, 1 material { skin { } } }
sphere { 0, 1 material { wax { } } }
sphere { 0, 1 material { marble { } } }
sphere { 0, 1 material { skin { preset "skin2" ior 1.3 roughness 0.4 profile dipole method circle group "head" } } }
sphere { 0, 1 material { skin { sigma_s <0.9, 1, 1.1> sigma_a <0.05, 0.1, 0.3> anisotropy 0.8 method volume } } }
sphere { 0, 1 material { wax { color rgb <0.9, 0.8, 0.5> radius <3, 2, 1> profile gaussian method fullcircle } } }
sphere { 0, 1 material { marble { image "marble.png" radius <5, 4, 3> normal_map "n.png" strength 0.5 method disk } } }
sphere { 0, 1 material { skin { color rgb 0.5 profile sum_of_gaussians normal_map "skin_n.png" } emission rgb 0.1 } }
sphere { 0, 1 material { marble { preset "apple" } } }
sphere { 0, 1 material { marble { preset "chicken1" } } }
sphere { 0, 1 material { marble { preset "chicken2" } } }
sphere { 0, 1 material { marble { preset "cream" } } }
sphere { 0, 1 material { marble { preset "ketchup" } } }
sphere { 0, 1 material { marble { preset "marble" } } }
sphere { 0, 1 material { marble { preset "potato" } } }
sphere { 0, 1 material { marble { preset "skimmilk" } } }
sphere { 0, 1 material { marble { preset "skin1" } } }
sphere { 0, 1 material { marble { preset "skin2" } } }
sphere { 0, 1 material { marble { preset "wholemilk" } } }
#declare Wax = material { wax { radius <1, 1, 1> } }
sphere { 0, 1 material { Wax } }
sphere { 0, 1 material { Wax emission rgb 2 } }
#declare Tex = texture { pigment { rgb 0.3 } }
sphere { 0, 1 texture { Tex } }
sphere { 0, 1 texture { Tex finish { specular 1 } } }
