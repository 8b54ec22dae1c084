// sss_methods.pov: the four SSS methods side by side on one wax: circle, fullcircle, disk and
// volume (per-material `method`), a sphere each, under a side light.
// render: -W 64 -H 32 --spp 64 --seed 6
// compare: --fail 0.05 --fail-percent 1
global_settings { mm_per_unit 10 }
camera { location <0, 1.2, -6.5> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 4, -2> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb <0.2, 0.22, 0.25> } intensity 1 }
#declare Ball = sphere { <0, 0.55, 0>, 0.55 }
object { Ball translate <-1.8, 0, 0> material { wax { method circle } } }
object { Ball translate <-0.6, 0, 0> material { wax { method fullcircle } } }
object { Ball translate <0.6, 0, 0> material { wax { method disk } } }
object { Ball translate <1.8, 0, 0> material { wax { method volume } } }
plane { y, 0 material { diffuse { color rgb 0.5 } } }
