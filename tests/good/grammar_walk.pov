// grammar_walk: one example of every rule of grammar/scene.ebnf; each `rule:` comment names the
// rules the next lines use (tests/lang/grammar_walk.sh checks that none is missing).
// rule: comment, scene, statement
/* a block comment */
// rule: directive, version, number
#version 3.7;
// rule: declare, identifier, expression, logical, comparison, additive, term, unary, primary, float
#declare A = -(1 + 2) * 3 / 3 + !0 - (1 < 2 & 2 <= 2 | 1 = 1 & 1 != 2 & 2 >= 1 & 2 > 1) + ("a" < "b" ? 1 : 0);
// rule: vector_literal, vector, call, function, string, colour
#declare V = <vlength(<3, 4, 0>), sin(0), clock>; #declare Vt = vturbulence(2, 0.5, 6, V);
#declare S = "tex.png";
#declare C = color rgb <1, 0.5, 0.25>;
// rule: deprecation
#declare deprecated once "use Ball" OldBall = 1;
// rule: block_value, trace_call, inside_call, object_ref
#declare Ball = sphere { 0, 1 } #declare TraceN = <0, 0, 0>; #declare TraceP = trace(Ball, <0, 0, -5>, z, TraceN); #declare InBall = inside(Ball, 0); #declare ObjPig = pigment { object { Ball color rgb 0 color rgb 1 } }
// rule: if, token
#if (A < 0) sphere { 0, 2 } #else sphere { 0, 3 } #end
// rule: ifdef, undef
#declare Gone = 1;
#undef Gone
#ifdef (Gone) sphere { 0, 4 } #end
#ifndef (Gone) sphere { 0, 5 } #else sphere { 0, 6 } #end
// rule: message
#debug ""
#if (0) #warning "skipped" #error "skipped" #end
// rule: elseif
#if (0) sphere { 0, 9 } #elseif (1) sphere { 0, 10 } #else sphere { 0, 11 } #end
// rule: while
#declare I = 0;
#while (I < 2) #declare I = I + 1; #end
// rule: for
#for (F, 1, 0, -1) #end
// rule: switch, case, range, break
#switch (2) #case (1) sphere { 0, 7 } #range (2, 3) #break #else sphere { 0, 8 } #end
// rule: macro, macro_param, macro_call
#macro Grow(R, optional S) #declare R = R + 1; #end
#declare Size = 1;
Grow(Size) Grow(Size, 2)
// rule: macro_arg
#macro Paint_Ball(P) sphere { 0, 1 pigment { P } } #end
Paint_Ball(pigment { rgb 0.5 })
// rule: fopen, read, fclose, data_file, data_value, write
#fopen Data "data/points.txt" read
#read (Data, Count, Radius)
#fclose Data
#if (defined(Data)) #fopen Out "never.txt" write #write (Out, Count, "\n") #end
// rule: include
#include "walk.inc"
// rule: global_settings, integer, ignored_setting, balanced
global_settings { mm_per_unit 10 max_trace_level 4 assumed_gamma 1 radiosity { count 9 media { off } } ambient_light 0 adc_bailout 0.01 charset ascii hf_gray_16 }
// rule: camera, projection, camera_item
camera { cylinder 2 location <0, 1, -5> look_at 0 sky y direction z angle 50 right x up y aperture 0.1 focal_point 0 blur_samples 4, 16 confidence 0.9 variance 0.001 translate x rotate y*5 scale 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> }
// rule: light_source
light_source { <0, 5, 0>, color C intensity 2 radius 0.5 }
light_source { <0, 5, 0> rgb 1 spotlight point_at 0 radius 10 falloff 20 }
light_source { <0, 5, 0> rgb 1 parallel point_at 0 }
// rule: background
background { rgb 0.1 }
// rule: sky_sphere
#declare Sky = sky_sphere { image "sky.exr" }
sky_sphere { Sky intensity 1 rotate y * 10 }
// rule: object_item, sphere, modifier, object_flag
sphere { V, 1 translate x rotate y * 30 scale 2 scale <1, 2, 3> matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> no_shadow hollow }
// rule: box, plane
box { -1, 1 }
plane { y, 0 }
// rule: mesh, triangle, smooth_triangle, tri_uv, inside_vector
mesh { triangle { 0, x, y } smooth_triangle { 0, -z, x, -z, y, -z uv_vectors <0, 0>, <1, 0>, <0, 1> } inside_vector z }
mesh { file "model.obj" }
// rule: mesh2, list
mesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 1, -z } uv_vectors { 3, <0, 0>, <1, 0>, <0, 1> }
        face_indices { 1, <0, 1, 2> } normal_indices { 1, <0, 0, 0> } uv_indices { 1, <0, 1, 2> } inside_vector <0, 0, 1> }
// rule: subdivision_surface, subd_item, crease_list, corner_list
subdivision_surface {
  vertex_vectors { 4, 0, x, x + y, y } faces { 1, <0, 1, 2, 3> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> } uv_faces { 1, <0, 1, 2, 3> }
  creases { 1, <0, 1>, 2 } corners { 1, 2, 1 } scheme catmull_clark boundary edge_only level 2
}
subdivision_surface { file "cage.obj" scheme loop boundary edge_and_corner max_edge 1 }
// rule: instance, union
union { object { Ball } sphere { x, 0.5 } translate y }
// rule: light_group
light_group { light_source { <0, 9, 0> color 1 } sphere { -x, 0.5 } global_lights on translate y }
// rule: material, material_item, sss_block, sss_param
sphere { 0, 1 material { diffuse { color C } } }
sphere { 0, 1 material { diffuse { image S } emission rgb 0.5 } }
sphere { 0, 1 material { skin { preset "skin2" sigma_a <0.1, 0.2, 0.3> ior 1.3 roughness 0.3 profile dipole
  normal_map "n.png" strength 0.5 anisotropy 0.1 method circle group "g" } } }
sphere { 0, 1 material { wax { color rgb 0.5 radius <1, 2, 3> profile gaussian method fullcircle } } }
sphere { 0, 1 material { marble { image "m.png" radius 2 profile burley method disk } } }
sphere { 0, 1 material { marble { sigma_s 0 + 2 sigma_a 0.01 } } }
#declare Paint0 = pigment { rgb <0, 0, 1> }
// rule: texture, pigment, finish, interior
sphere { 0, 1 texture { pigment { rgb 1 } finish { diffuse 0.5 specular 0.2 roughness 0.1 } } interior { ior 1.3 } }
sphere { 0, 1 material { texture { pigment { image_map { png "t.png" } } } interior { ior 1.2 } } }
// rule: postfix, member, colour_item, array, array_items, array_item, index, defined
#declare Ar = array[2] { C.red, defined(Ar[0]) }
#declare Balls = array[1] { sphere { 0, 1 } }
object { Balls[0] }
#declare Ar[1] = (color rgbf <1, 1, 1, 0.5> transmit 0.25).filter;
// rule: pigment_body, pattern, block_pattern, block_item, pattern_modifier, turb_param, wave, colour_map, colour_entry
sphere { 0, 1 pigment { checker rgb 1, pigment { bozo turbulence 0.5 octaves 3 omega 0.6 lambda 2.5 poly_wave 2 } } }
sphere { 0, 1 pigment { marble frequency 2 phase 0.1 colour_map { [0 rgb 0] [0.5, 0.7 rgb 1 rgb 0.5] [1 rgb <1, 0, 0>] } scale 2 } }
// rule: pigment_map, pigment_entry, warp, repeat_item, black_hole_item, mapping_item
#declare Cm = color_map { [0 rgb 0] [1 rgb 1] }; #declare WarpPig = pigment { checker warp { toroidal orientation y dist_exp 1 major_radius 2 } warp { planar y, 1 } warp { cubic } }
sphere { 0, 1 pigment { gradient y pigment_map { [0 checker rgb 0, rgb 1] [1 Paint0] } warp { repeat x offset y flip x } warp { black_hole 0, 1 strength 2 falloff 1 inverse repeat 1 } warp { turbulence 0.2 octaves 2 } } }
sphere { 0, 1 pigment { wood color_map { Cm } brick_size 2 mortar 0.1 agate_turb 1 control0 0 control1 1 quick_color rgb 1 uv_mapping } }
sphere { 0, 1 material { marble { pigment { granite scale < 2 1 1 > } } } }
sphere { 0, 1 pigment { pigment_pattern { checker rgb 0, rgb 1 } color_map { [0 rgb <1, 0, 0>] [1 rgb 1] } } normal { pigment_pattern { bozo } 0.3 } }
#declare Sky0 = sky_sphere { pigment { gradient y } pigment { bozo color_map { [0 rgbt 1] [1 rgb 1] } } scale 2 };
// rule: normal, normal_modifier, bump_map
#declare Nb = normal { bumps 0.4 scale 0.2 };
sphere { 0, 1 texture { pigment { rgb 1 } normal { Nb accuracy 0.01 } } normal { ripples, 0.3 bump_size 0.6 frequency 4 } }
sphere { 0, 1 normal { bump_map { png "t.png" map_type 2 bump_size 2 use_color } 1.5 } }
// rule: image_map, image_item
sphere { 0, 1 pigment { image_map { png "t.png" map_type 1 once interpolate 2 filter all 0.5 transmit all 0.1 } } }
// rule: transform_item, transform, default
#declare Turn = transform { rotate y * 90 translate x inverse }
#declare Paint = pigment { rgb <1, 0, 0> }
#declare Gloss = finish { specular 0.5 }
#declare Glass = interior { ior 1.5 }
// rule: interior_item
#declare Fading = interior { Glass fade_distance 2 fade_power 1001 fade_colour rgb <1, 0.5, 0.2> fade_color rgb 0.5 }
sphere { 0, 1 pigment { rgbft <1, 1, 1, 0.3, 0.4> } interior { Fading ior 1.33 } }
#declare Eye = camera { location -z }
#declare Lamp = light_source { y, 1 }
light_source { Lamp translate x }
#default { texture { pigment { Paint } } finish { Gloss } }
sphere { 0, 1 transform Turn transform { Turn translate y } texture { pigment { Paint rotate x } finish { Gloss } } interior { Glass } }
// rule: function_value, fn_params, fn_body, fn_expression, value_call
#declare Fa = function(a, b) { a < b ? a*b : sqr(a) + sin(b) }
#declare Fb = function { x + Fa(y, z) }
#declare Fc = function { internal(61) }
#declare Fd = function { pattern { agate } } #declare Ff = function { pigment { function { Fd(x, y, z) * 2 } color_map { Cm } } } #declare Fg = Ff(0.5, 0.5, 0.5).gray + Fd(1, 2, 3);
#declare Fe = function { transform { Turn } }
#declare Fv = Fb(1, 2, 3) + Fc(1, 1, 1, 0.5) + Fe(1, 0, 0).x;
// rule: spline, spline_kind
#declare Sa = spline { cubic_spline 0, <0, 0> 1, <1, 2>, 2, <2, 1> 3, <3, 3> }
#declare Sb = spline { Sa natural_spline 4, <1, 1> }
#declare Ff = function { spline { Sb } }
#declare Sv = Sa(1.5) + Sb(2, linear_spline) + Ff(0.5).y;
// rule: macro_arg
#macro Apply(Fn, Tr) Fn(1, 2, 3) + vlength(vtransform_walk(Tr)) #end
#macro vtransform_walk(T) #local Fw = function { transform { T } } Fw(1, 0, 0) #end
#declare Av = Apply(function { x + y*z }, transform { translate y });
// rule: finish_item, reflection_item
sphere { 0, 1 finish { ambient 0.1 diffuse albedo 0.6 phong 0.5 phong_size 20 metallic reflection { 0.1, 0.5 falloff 2 } } }
// rule: media, media_item, scattering, density
#declare Dens = density { bozo density_map { [0 rgb 0] [1 rgb 1] } }
#declare Fume = media { scattering { 5, rgb 0.2 eccentricity 0.5 extinction 0.8 } method 3 samples 2, 4 jitter 0.1 }
box { 0, 1 pigment { rgbt 1 } hollow interior { media { Fume absorption 0.1 emission 0.1 density { Dens scale 0.5 } translate x } } }
// rule: fog, fog_item
fog { fog_type 2 distance 30 color rgb 0.5 fog_offset 1 fog_alt 2 }
// rule: pov_shape, lathe, spline_type, uv_list, sor, prism, sphere_sweep, sweep_sphere
#declare Vase = lathe { quadratic_spline 4, <0, 0>, <1, 0>, <1, 1>, <0.5, 2> sturm }
object { Vase translate x }
sor { 4, <0, 0>, <1, 0>, <0.5, 1>, <0.7, 2> open }
prism { conic_sweep bezier_spline 0.5, 1, 4, <1, 0>, <1, 1>, <0, 1>, <1, 0> }
sphere_sweep { b_spline 4, <0, 0, 0>, 0.5, <1, 1, 0> 0.5, <2, 0, 0>, 0.5, <3, 1, 0>, 0.5 tolerance 1e-4 }
// rule: blob, blob_item, blob_comp_mod, text
blob { threshold 0.6 component 1, 1, <0, 0, 0> sphere { <1, 0, 0>, 1, strength 1 scale 2 }
	cylinder { <0, 0, 0>, <0, 1, 0>, 0.5, -0.5 pigment { rgb 0 } } }
text { ttf "/usr/share/povray-3.7/include/timrom.ttf" "circe" 0.5, <0.1, 0, 0> }
// rule: bicubic_patch, bicubic_item
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 uv_vectors <0, 0>, <1, 0>, <1, 1>, <0, 1>
	<0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 1, 0>, <1, 1, 1>, <2, 1, 1>, <3, 1, 0>
	<0, 2, 0>, <1, 2, 1>, <2, 2, 1>, <3, 2, 0>, <0, 3, 0>, <1, 3, 0>, <2, 3, 0>, <3, 3, 0> }
// rule: isosurface, iso_function, iso_item
isosurface { function { x * x + y * y + z * z - 0.25 } contained_by { sphere { 0, 1 } } threshold 0 accuracy 0.01
	max_gradient 2 evaluate 1, 10, 0.99 open max_trace 2 all_intersections translate 3 * y }
// rule: parametric, param_item
parametric { function { u } function { v } function { u * v } <0, 0>, <1, 1> contained_by { box { -1, 1 } }
	max_gradient 1 accuracy 0.01 precompute 10 x, y, z translate 3 * y }
// rule: julia_fractal, julia_item
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 6 precision 10 slice <0, 0, 0, 1>, 0
	translate 3 * y }
// rule: object_triangle
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> translate 3 * y }
// rule: shape, cylinder, cone, torus, disc, polygon, superellipsoid, height_field, quadric, poly
cylinder { <0, 0, 0>, <0, 1, 0>, 0.5 open translate x }
cone { 0, 1 y 0.2 }
torus { 1, 0.25 sturm }
disc { 0, y, 2, 0.5 }
polygon { 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
superellipsoid { <0.5, 1> }
height_field { png "hf.png" smooth water_level 0.1 }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
#declare Cubic = cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> }
#declare Poly = poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
// rule: texture
#declare Layered = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
sphere { 0, 1 texture { Layered } texture { pigment { rgbf <0, 1, 0, 0.5> } } }
// rule: csg
difference { intersection { sphere { 0, 1 } box { -1, 1 } } merge { cylinder { -x, x, 0.2 } plane { y, 0 inverse } } clipped_by { box { -2, 2 } } bounded_by { box { -2, 2 } } }
// rule: subsurface_settings
global_settings { subsurface { radiosity off } }
// rule: normal_map, normal_entry, pattern_item
sphere { 0, 1 pigment { crackle form <1, 0, 0> metric 1 offset 0.1 solid } normal { average normal_map { [1 bumps 0.5] [2 gradient x, 0.3 scale 2] } } }
sphere { 0, 1 pigment { julia <0, 1>, 10 exterior 2, 1 interior 1, 0.5 exponent 2 } }
// rule: texture_body, pattern_texture, texture_map
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } normal { bumps 0.2 } } scale 2 } }
sphere { 0, 1 texture { gradient y texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
// rule: tiles, quick_colour, slope_range
sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 quick_color rgb 0.5 } } tile2 texture { pigment { rgb 0 } } } scale 2 } }
sphere { 0, 1 pigment { slope { -y, 0, 0.5 altitude y, -1, 1 } } }
// rule: rainbow
rainbow { angle 42 width 5 direction z up y arc_angle 100 colour_map { [0 rgbf 1] [1 rgbf <1, 0, 0, 0.8>] } }
// rule: texture_list
mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 1, texture { pigment { rgb 0.5 } } } face_indices { 1, <0, 1, 2>, 0 } }
// rule: material_map
sphere { 0, 1 texture { material_map { png "t.png" once texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }
