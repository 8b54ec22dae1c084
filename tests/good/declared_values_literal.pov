// declared_values_literal: declared_values.pov with every declared value written as a literal.
global_settings { mm_per_unit 2 max_trace_level 7 assumed_gamma 1.5 }
camera { perspective location <0, 1, -5> look_at <0, 0.5, 0> sky <0, 1, 0> angle 40 right <1.5, 0, 0> up <0, 1, 0> aperture 0.25 focal_point <0, 0.5, 0> }
light_source { <0, 5, -5> rgb <1, 0.9, 0.8> }
light_source { <0, 5, -5>, rgb <1, 0.9, 0.8> intensity 3 radius 0.5 }
light_source { <0, 1, -5> rgb <1, 0.9, 0.8> * 0.5 spotlight radius 20 falloff 30 point_at <0, 0.5, 0> }
background { rgb <0.1, 0.2, 0.3> }
sky_sphere { image "sky.exr" intensity 0.5 rotate <0, 30, 0> }
sphere { <0, 1, -5>, 0.5 translate <0, 0.5, 0> rotate <0, 30, 0> scale 3 scale <1, 2, 1.5> }
box { <0, 1, -5>, <1.5, 0.5, 0> matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3> }
plane { <0, 1, 0>, 0.5 }
mesh { triangle { <0, 1, -5>, <0, 0.5, 0>, <1.5, 0, 0> } smooth_triangle { <0, 1, -5>, <0, 1, 0>, <0, 0.5, 0>, <0, 1, 0>, <1.5, 0, 0>, <0, 1, 0> } }
mesh2 { vertex_vectors { 3, <0, 1, -5>, <0, 0.5, 0>, <1.5, 0, 0> } normal_vectors { 3, <0, 1, 0>, <0, 1, 0>, <0, 1, 0> }
        uv_vectors { 3, <0.25, 0.75>, <0.25, 0.75>, <0.25, 0.75> } face_indices { 1, <0, 1, 2> } normal_indices { 1, <0, 1, 2> } uv_indices { 1, <0, 1, 2> } }
subdivision_surface { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> } faces { 1, <0, 1, 2, 3> }
        creases { 1, <0, 1>, 2.5 } corners { 1, 2, 2.5 } level 2 }
subdivision_surface { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> } faces { 1, <0, 1, 2, 3> } max_edge 0.5 }
sphere { 0, 1 material { diffuse { rgb <1, 0.9, 0.8> * 0.5 } emission rgb <0.1, 0.2, 0.3> } }
sphere { 0, 1 texture { pigment { rgb <0.1, 0.2, 0.3> } finish { diffuse 0.25 specular 0.25 roughness 0.25 } } interior { ior 1.4 } }
sphere { 0, 1 pigment { rgb <0.1, 0.2, 0.3> } }
sphere { 0, 1 material { skin { sigma_s <1, 0.9, 0.8> sigma_a <0.1, 0.2, 0.3> ior 1.4 roughness 0.25 anisotropy 0.25 normal_map "n.png" strength 0.25 group "g" } } }
sphere { 0, 1 material { wax { rgb <0.1, 0.2, 0.3> radius <1, 0.9, 0.8> } } }
sphere { 0, 1 material { marble { color rgb <0.1, 0.2, 0.3> radius <1, 0.9, 0.8> * 2 } } }
sphere { 0, 1 material { skin { preset "skin1" } } }
sphere { 0, 1 material { skin { image "albedo.png" radius <1, 0.9, 0.8> } } }
sphere { 0, 1 pigment { image_map { png "albedo.png" } } }
sphere { 0, 1 material { diffuse { image "albedo.png" } } }
mesh { file "n.png" }
subdivision_surface { file "sky.exr" }
