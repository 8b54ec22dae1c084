// declared_values: a declared float, vector, colour or string works everywhere a literal one may stand
// (issue 14.7: a light's colour, an SSS block's colour, and every other item). Its IR equals that
// of declared_values_literal.pov but for the source locations (tests/lang/good_scenes.sh checks).
#declare F = 0.5;  #declare F2 = 0.25;  #declare G = 1.5;  #declare N = 7;  #declare A = 40;
#declare V = <0, 1, -5>;  #declare LA = <0, 0.5, 0>;  #declare Up = <0, 1, 0>;  #declare R = <1.5, 0, 0>;
#declare Rot = <0, 30, 0>;  #declare W = rgb <1, 0.9, 0.8>;  #declare C = color rgb <0.1, 0.2, 0.3>;
#declare UV = <0.25, 0.75>;  #declare T = <0, 1, 2>;  #declare Q = <0, 1, 2, 3>;  #declare E = <0, 1>;
#declare M = <1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3>;  #declare Sky = "sky.exr";  #declare One = 1;
#declare Three = 3;  #declare Two = 2;  #declare K = 2.5;  #declare Ior = 1.4;  #declare NM = "n.png";
#declare Grp = "g";  #declare Pre = "skin1";  #declare Alb = "albedo.png";
#declare P0 = <0, 0, 0>;  #declare P1 = <1, 0, 0>;  #declare P2 = <1, 1, 0>;  #declare P3 = <0, 1, 0>;
global_settings { mm_per_unit Two max_trace_level N assumed_gamma G }
camera { perspective location V look_at LA sky Up angle A right R up Up aperture F2 focal_point LA }
light_source { <0, 5, -5> W }
light_source { <0, 5, -5>, W intensity Three radius F }
#declare Cone = 20; #declare Fall = 30;
light_source { V W * F spotlight radius Cone falloff Fall point_at LA }
background { C }
sky_sphere { image Sky intensity F rotate Rot }
sphere { V, F translate LA rotate Rot scale Three scale <One, Two, G> }
box { V, LA + R matrix M }
plane { Up, F }
mesh { triangle { V, LA, R } smooth_triangle { V, Up, LA, Up, R, Up } }
mesh2 { vertex_vectors { Three, V, LA, R } normal_vectors { Three, Up, Up, Up }
        uv_vectors { Three, UV, UV, UV } face_indices { One, T } normal_indices { One, T } uv_indices { One, T } }
subdivision_surface { vertex_vectors { 4, P0, P1, P2, P3 } faces { One, Q }
        creases { One, E, K } corners { One, Two, K } level Two }
subdivision_surface { vertex_vectors { 4, P0, P1, P2, P3 } faces { One, Q } max_edge F }
sphere { 0, One material { diffuse { W * F } emission C } }
sphere { 0, One texture { pigment { C } finish { diffuse F2 specular F2 roughness F2 } } interior { ior Ior } }
sphere { 0, One pigment { C } }
sphere { 0, One material { skin { sigma_s W sigma_a C ior Ior roughness F2 anisotropy F2 normal_map NM strength F2 group Grp } } }
sphere { 0, One material { wax { C radius W } } }
sphere { 0, One material { marble { color C radius W * 2 } } }
sphere { 0, One material { skin { preset Pre } } }
sphere { 0, One material { skin { image Alb radius W } } }
sphere { 0, One pigment { image_map { png Alb } } }
sphere { 0, One material { diffuse { image Alb } } }
mesh { file NM }
subdivision_surface { file Sky }
