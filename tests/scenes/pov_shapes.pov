// pov_shapes.pov: POV-Ray's lathe (cubic), sor, prism (a square with a square hole, conic),
// sphere_sweep (b_spline), blob (the subsurface demo's candle, in wax by the volume method,
// which refuses an open mesh) and text, tessellated at the accuracy their size asks for.
// render: -W 96 -H 64 --spp 32 --seed 6 -I /usr/share/povray-3.7/include
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 3, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 intensity 60 }
sky_sphere { pigment { color rgb 0.25 } intensity 1 } // circe's sky: it lights (a POV-Ray background would not, without radiosity)
plane { y, 0 material { diffuse { color rgb 0.5 } } }
lathe { cubic_spline 7, <0, -0.5>, <0, 0>, <0.9, 0.1>, <0.5, 1>, <0.7, 2>, <0, 2.2>, <0, 2.5>
	translate <-3, 0, 0> material { diffuse { color rgb <0.8, 0.3, 0.2> } } }
sor { 6, <0, 0>, <0.6, 0>, <0.8, 0.6>, <0.3, 1.2>, <0.5, 1.8>, <0.5, 2>
	translate <-1.3, 0, 1> material { diffuse { color rgb <0.3, 0.6, 0.8> } } }
prism { conic_sweep linear_spline 0.6, 1, 10, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
	<-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
	rotate x * 180 translate <1.4, 1, -0.5> material { diffuse { color rgb <0.7, 0.7, 0.3> } } }
sphere_sweep { b_spline 6, <-3, 3, 1>, 0.15, <-2, 3.6, 1>, 0.2, <-1, 3, 1>, 0.25, <0, 3.6, 1>, 0.2,
	<1, 3, 1>, 0.15, <2, 3.6, 1>, 0.1 material { diffuse { color rgb <0.4, 0.8, 0.4> } } }
blob { threshold 0.5
	cylinder { <0.0, 0.0, 0.0>, <0.0, 2.0, 0.0>, 1.0, 1.0 }
	sphere { <0.0, 2.5, 0.0>, 0.8, -2.0 }
	sphere { <0.0, -0.52, 0.0>, 0.8, -2.0 }
	sphere { <0.0, 2.0, -0.5>, 0.1, -0.2 }
	cylinder { <0.0, 1.88, -0.52>, <0.0, 1.5, -0.52>, 0.05, 0.2 }
	sphere { <0.0, 1.5, -0.55>, 0.07, 0.2 }
	scale 0.8 rotate -y * 45 translate <3, 0, 0.5> material { wax { method volume } } }
text { ttf "timrom.ttf" "circe 3.7" 0.2, <0.02, 0, 0>
	scale 0.8 translate <-1.6, 0.02, -2.2> material { diffuse { color rgb 0.9 } } }
